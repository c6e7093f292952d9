"""CANopenObjectList → objects and sub-objects, with the ApplicationProcess parameters they reference.

CiA 311 lets a file state an entry's data on the CANopenObject itself
(`dataType`, `accessType`, `defaultValue`...) or on the `parameter` its
`uniqueIDRef` names (a type element, `access`, `defaultValue`, `allowedValues`,
CANopenNode `property` elements). A parameter's statement wins, as CANopenEditor
reads it; whatever the model has no field for is kept in `extra`.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from ..canopennode.info import PROPERTY_PREFIX, read_property
from ..eds.values import parse_value
from ..model import (
    AccessType,
    CanopenNodeInfo,
    Device,
    Object,
    ObjectKind,
    SubObject,
    ValueKind,
    Variable,
)
from ..model.assemble import fresh
from .context import ReadContext
from .fragments import fragment, one_line
from .safe import Element
from .vocabulary import (
    DOMAIN,
    EDS_PROPERTY,
    OBJECT_ATTRIBUTES,
    OCTET_STRING,
    PARAMETER_ACCESS,
    PDO_MAPPINGS,
    TYPE_ELEMENTS,
)

_VALUE_FIELDS = {"defaultValue": "default", "lowLimit": "low_limit", "highLimit": "high_limit"}
_VALUE_FIELDS["actualValue"] = "parameter_value"


@dataclass
class _Pending:
    """A value's text, typed once every object (and so every DEFTYPE) is known."""

    var: Variable
    owner: Object
    field: str
    text: str
    where: tuple[int, int]
    key: str


class ObjectReader:
    def __init__(self, ctx: ReadContext, device: Device, parameters: dict[str, Element]) -> None:
        self.ctx = ctx
        self.device = device
        self.parameters = parameters
        self.pending: dict[tuple[int, str], _Pending] = {}  # by (id(var), field): a later statement replaces
        self.used: set[str] = set()

    def read_list(self, object_list: Element) -> list[Element]:
        """Reads every CANopenObject; returns the children that are not objects."""
        others: list[Element] = []
        for element in object_list.children:
            if element.local != "CANopenObject":
                others.append(element)
                continue
            index = self._hex(element, "index", 0xFFFF)
            if index is None:
                continue
            if index in self.device.objects:
                first = self.device.objects[index].origin
                self.ctx.error(
                    "XDD008",
                    f"object {index:04X}h given again (first on line {first.line if first else 0}); ignored",
                    element,
                )
                continue
            obj = fresh(Object, {"index": index})
            self._entry(obj, obj, element, has_subs=any(c.local == "CANopenSubObject" for c in element.children))
            for child in element.children:
                if child.local == "CANopenSubObject":
                    self._sub(obj, child)
                else:
                    self._unknown_child(obj, child)
            obj.subs = dict(sorted(obj.subs.items()))
            self.device.objects[index] = obj
        return others

    def _sub(self, obj: Object, element: Element) -> None:
        subindex = self._hex(element, "subIndex", 0xFF)
        if subindex is None:
            return
        if subindex in obj.subs:
            self.ctx.error("XDD008", f"sub-index {subindex:X}h of {obj.index:04X}h given again; ignored", element)
            return
        sub = fresh(SubObject, {})
        self._entry(sub, obj, element, has_subs=False)
        for child in element.children:
            self._unknown_child(sub, child)
        obj.subs[subindex] = sub

    def _hex(self, element: Element, attr: str, top: int) -> int | None:
        text = element.attrs.get(attr)
        if text is None:
            self.ctx.error("XDD006", f"<{element.local}> without its required {attr!r} attribute; ignored", element)
            return None
        try:
            value = int(text, 16)
        except ValueError:
            value = -1
        if not 0 <= value <= top:
            self.ctx.error("XDD007", f"{attr}={text!r} is not a hex number up to {top:X}h; ignored", element, attr)
            return None
        return value

    def _entry(self, var: Variable, owner: Object, element: Element, has_subs: bool) -> None:
        origin = self.ctx.origin(element)
        var.origin = origin
        extra: dict[str, str] = {}
        for attr, text in element.attrs.items():
            key = OBJECT_ATTRIBUTES.get(attr)
            if key is None:
                if not attr.startswith("xmlns"):
                    self.ctx.warning("XDD011", f"unknown attribute {attr!r} of <{element.local}>; kept", element, attr)
                    extra[attr] = text
                continue
            if key:
                self.ctx.mark(origin, key, element, attr)
                self._attribute(var, owner, element, attr, text, key, extra)
        if "name" not in element.attrs:
            self.ctx.error("XDD006", f"<{element.local}> without its required 'name' attribute", element)
        ref = element.attrs.get("uniqueIDRef")
        if ref:
            parameter = self.parameters.get(ref)
            if parameter is None:
                self.ctx.warning("XDD009", f"uniqueIDRef {ref!r} names no parameter", element, "uniqueIDRef")
            else:
                self.used.add(ref)
                self._parameter(var, owner, parameter, has_subs, extra, _standard_type(owner, element))
        var.extra = extra
        word = element.attrs.get("PDOmapping")
        if word in ("no", "optional", "default", "TPDO", "RPDO"):  # now that the access is known
            var.state_pdo_mapping(word)

    def _attribute(
        self, var: Variable, owner: Object, element: Element, attr: str, text: str, key: str, extra: dict[str, str]
    ) -> None:
        if attr == "name":
            var.name = text
        elif attr in _VALUE_FIELDS:
            self._defer(var, owner, _VALUE_FIELDS[attr], text, element, attr, key)
        elif attr == "denotation":
            var.denotation = text
        elif attr == "PDOmapping":
            if text not in PDO_MAPPINGS:
                self.ctx.warning("XDD007", f"PDOmapping={text!r} is none of {', '.join(PDO_MAPPINGS)}", element, attr)
            var.pdo_mapping = text not in ("no", "")
            if text not in ("no", "optional", "default", "TPDO", "RPDO"):
                extra["PDOmapping"] = text
        else:
            self._typed_attribute(var, element, attr, text, extra)

    def _typed_attribute(self, var: Variable, element: Element, attr: str, text: str, extra: dict[str, str]) -> None:
        value: Any = None
        try:
            if attr == "objectType":
                value = ObjectKind(int(text, 0))
            elif attr in ("dataType", "objFlags"):
                value = int(text, 16)
            elif attr == "accessType":
                value = AccessType(text)
            elif attr == "subNumber":
                value = int(text, 0)
        except ValueError:
            value = None
        if value is None:
            self.ctx.warning("XDD007", f"{attr}={text!r} cannot be read; kept as text", element, attr)
            extra[attr] = text
            return
        field = {"objectType": "object_type", "dataType": "data_type", "objFlags": "obj_flags"}.get(attr)
        field = field or {"accessType": "access", "subNumber": "sub_number"}[attr]
        if field == "sub_number" and not isinstance(var, Object):
            extra[attr] = text
            return
        setattr(var, field, value)

    def _defer(
        self, var: Variable, owner: Object, field: str, text: str, element: Element, attr: str, key: str
    ) -> None:
        self.pending[id(var), field] = _Pending(var, owner, field, text, self.ctx.where(element, attr), key)

    def _parameter(
        self, var: Variable, owner: Object, parameter: Element, has_subs: bool, extra: dict[str, str],
        standard: int | None,
    ) -> None:  # fmt: skip
        """`standard`: the data type CiA 301 gives the entry, if it defines one."""
        origin = var.origin
        assert origin is not None
        access = parameter.attrs.get("access")
        if access is not None:
            self.ctx.mark(origin, "AccessType", parameter, "access")
            if access in PARAMETER_ACCESS:
                var.access = PARAMETER_ACCESS[access]
            else:
                if access != "noAccess":
                    self.ctx.warning("XDD007", f"access={access!r} is not a CiA 311 access", parameter, "access")
                extra["access"] = access
        elif not has_subs and var.access is None:
            var.access = AccessType.RO  # CiA 311: a parameter's access defaults to read
        for name, text in parameter.attrs.items():
            if name not in ("uniqueID", "access") and not name.startswith("xmlns"):
                extra[f"parameter@{name}"] = text
        type_element: Element | None = None
        info = fresh(CanopenNodeInfo, {})
        for child in parameter.children:
            if child.local in TYPE_ELEMENTS:
                type_element = child
            elif not self._parameter_child(var, owner, child, info, extra):
                extra[f"parameter.{child.local}"] = fragment(child)
        if type_element is not None and "DataType" not in origin.keys:
            self.ctx.mark(origin, "DataType", type_element)
            index = TYPE_ELEMENTS[type_element.local]
            stated = self.pending.get((id(var), "default"))
            if index == OCTET_STRING and not (stated and stated.text) and standard != OCTET_STRING:
                # CANopenEditor writes DOMAIN as a BITSTRING without a default value; an entry CiA 301
                # defines as OCTET_STRING (1023h/1025h Command and Reply) stays one.
                index = DOMAIN
            var.data_type = index
        if not info.is_empty():
            var.canopennode = info

    def _parameter_child(
        self, var: Variable, owner: Object, child: Element, info: CanopenNodeInfo, extra: dict[str, str]
    ) -> bool:
        origin = var.origin
        assert origin is not None
        local = child.local
        if local in ("defaultValue", "actualValue") and "value" in child.attrs:
            # A value on the parameter replaces one on the object.
            field = _VALUE_FIELDS[local]
            key = "DefaultValue" if local == "defaultValue" else "ParameterValue"
            self.ctx.mark(origin, key, child, "value")
            self._defer(var, owner, field, child.attrs["value"], child, "value", key)
        elif local == "allowedValues":
            return self._allowed(var, owner, child)
        elif local == "denotation":
            label = child.child("label")
            var.denotation = (label.text if label is not None else child.text).strip()
            self.ctx.mark(origin, "Denotation", child)
        elif local == "property":
            return self._property(child, info, extra)
        elif local == "description":
            extra["Description"] = one_line(child.text)
        elif local == "label":
            if child.text != var.name:
                extra["label"] = one_line(child.text)
        elif local == "dataTypeIDRef":
            if not (var is owner and owner.has_subs):  # an ARRAY's or RECORD's type is rebuilt from its subs
                extra["dataTypeIDRef"] = child.attrs.get("uniqueIDRef", "")
        else:
            return False
        return True

    def _allowed(self, var: Variable, owner: Object, allowed: Element) -> bool:
        ranges = allowed.all("range")
        if len(ranges) != 1 or len(allowed.children) != 1:
            return False  # value lists and several ranges have no EDS form: kept whole
        origin = var.origin
        assert origin is not None
        for local, field, key in (("minValue", "low_limit", "LowLimit"), ("maxValue", "high_limit", "HighLimit")):
            bound = ranges[0].child(local)
            if bound is not None and "value" in bound.attrs:
                self.ctx.mark(origin, key, bound, "value")
                self._defer(var, owner, field, bound.attrs["value"], bound, "value", key)
        return True

    def _property(self, element: Element, info: CanopenNodeInfo, extra: dict[str, str]) -> bool:
        name = element.attrs.get("name", "")
        text = element.attrs.get("value", "")
        read = read_property(name, text)
        if name.startswith(EDS_PROPERTY):
            extra[name[len(EDS_PROPERTY) :]] = text  # an EDS key with no CiA 311 form, kept by our writer
            return True
        if read is None:
            if name.startswith(PROPERTY_PREFIX):
                self.ctx.warning("XDD007", f"property {name}={text!r} cannot be read; kept as text", element)
            extra[f"property.{name}"] = text
            return True
        setattr(info, *read)
        return True

    def _unknown_child(self, var: Variable, child: Element) -> None:
        self.ctx.warning(
            "XDD010", f"unknown element <{child.local}> in <{child.parent.local if child.parent else ''}>; kept", child
        )
        var.extra = {**var.extra, f"<{child.local}>": fragment(child)}

    def type_values(self) -> None:
        for pending in self.pending.values():
            var = pending.var
            dtype = self.device.entry_type(var, pending.owner)
            kind = dtype.kind if dtype is not None else None
            text = pending.text
            if kind is ValueKind.BOOL and text.strip().lower() in ("true", "false"):
                text = "1" if text.strip().lower() == "true" else "0"
            parsed = parse_value(text, kind, dtype.bits if dtype else None, dtype.name if dtype else "this type")
            setattr(var, pending.field, parsed.value)
            for note in parsed.notes:
                if not note.silent_in_xdd:
                    severity = note.in_xdd or note.severity
                    self.ctx.report.add(note.code, severity, f"{pending.key}: {note.message}", *pending.where)


def _standard_type(owner: Object, element: Element) -> int | None:
    """The data type CiA 301 gives the entry `element` describes (a sub-object's by its subIndex), if any."""
    from ..model.cia301.definitions import definition

    found = definition(owner.index)
    try:
        subindex = int(element.attrs.get("subIndex", "0"), 16)
    except ValueError:
        return None
    entry = found.entry(subindex) if found is not None else None
    return entry.data_type if entry is not None else None
