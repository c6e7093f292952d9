"""CANopenNode v4 in one place: every fact of the stack and of CANopenEditor's projects that the readers, checks,
views, renderers and commands use.

- `info`: what a project says about an object (`CanopenNodeInfo`), and where each format says it: CANopenEditor's
  `CO_*` XDD properties, the EDS `;StorageLocation=` comment.
- `profile`: what the stack needs: count labels, storage groups, the counts CANopen.c checks, the objects
  CO_CANopenInit reads, the build configuration (`CO_CONFIG_*`), the C names of attributes and object types.
- `editor`: how CANopenEditor reads a project and writes its OD: PDO attribute bits, defaults CiA 306 cannot read,
  the C names of display names.
- `overrides`: the `<stem>.canopennode.toml` file beside a device description.

The work stays with its layer: the CNO rules in lint/canopennode.py, the view (what OD.h/OD.c hold) in
views/canopennode.py, the C spelling in render/canopennode.py and templates/canopennode/, the `gen` steps in
cli/canopennode.py. This package imports only the model's CiA 301 numbers and data types; it loads nothing on its
own so that the model can take `CanopenNodeInfo` from it.
"""
