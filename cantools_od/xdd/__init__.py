"""CiA 311 XML device descriptions (XDD, XDC): reader and writers."""


def is_xml(data: bytes) -> bool:
    """Whether the content is XML (an XDD/XDC) rather than an EDS/DCF: it starts with `<`."""
    head = data[:4096].lstrip(b"\xef\xbb\xbf").lstrip()
    return head.startswith(b"<") or head.startswith(b"\xff\xfe<") or head.startswith(b"\xfe\xff\x00<")
