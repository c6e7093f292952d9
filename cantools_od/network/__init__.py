"""Networks: a bus description (lely dcfgen's / ros2_canopen's bus.yml) read into a typed model, planned
into each slave's boot-time SDO writes and PDOs, and written as the master's configuration, checked,
measured (bus load) and described for trace tools (DBC)."""
