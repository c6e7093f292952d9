"""A device description on a live CAN bus: `simulate` serves it as a node, `probe` reads a node against it.

Both run on python-can (the bus) and python-canopen (the CANopen services)."""

import logging

for _library in ("canopen", "can"):
    # Their log lines (a retried request, a value outside its limits, a bus not shut down) are the commands'
    # business: what matters reaches the user as a finding or as one line.
    logging.getLogger(_library).addHandler(logging.NullHandler())
    logging.getLogger(_library).propagate = False
