"""Target-neutral views of a device that renderers and CLI output share."""
