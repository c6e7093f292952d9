"""The NMT service (CiA 301 §7.2.8.3.1): the commands a master sends (CAN-ID 0: command, node-ID or 0 for all)
and the states a node reports in its heartbeat."""

from __future__ import annotations

START, STOP, ENTER_PRE_OPERATIONAL, RESET_NODE, RESET_COMMUNICATION = 0x01, 0x02, 0x80, 0x81, 0x82
RESETS = (RESET_NODE, RESET_COMMUNICATION)
ALL_NODES = 0  # the node-ID of a command for every node

BOOT_UP, STOPPED, OPERATIONAL, PRE_OPERATIONAL = 0x00, 0x04, 0x05, 0x7F  # heartbeat states
