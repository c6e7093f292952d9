"""A synthetic EDS of a given size, for the scale benchmark (bench_scale.py).

    python bench/synthetic_eds.py 50M -o big.eds

The device has the mandatory objects, 4 RPDOs and 4 TPDOs mapping its first VARs, and
manufacturer/profile objects from 0x2000 up: 40 % VAR, 60 % ARRAY/RECORD whose sub-object count
grows with the requested size (an index has at most 255 sub-objects and there are 0x8000 indices
from 0x2000 to 0x9FFF, so a large file has more sub-objects per object). Every key is spelled out
as tools write it; output is deterministic for a given size.

With `--canopennode` the file also passes `lint --profile canopennode` (so that `gen -t canopennode`
renders it): it adds the communication objects CANopenNode's CANopen.c needs (1003h, 1014h, 1016h,
1017h), and an ARRAY's elements share one access type.
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Iterator
from pathlib import Path

FIRST, LAST = 0x2000, 0x9FFF
_VAR_TYPES = [  # (data type, default)
    (0x0007, "0x12345678"),
    (0x0006, "0x1234"),
    (0x0005, "0x12"),
    (0x0004, "-100000"),
    (0x0003, "-1000"),
    (0x0002, "-10"),
    (0x0001, "1"),
    (0x0008, "1.5"),
    (0x0009, "text"),
]
_ACCESS = ["rw", "ro", "rww", "rwr", "const"]
_SUB_BYTES = 110  # about what one sub-object section takes


def _entry(name: str, data_type: int, access: str, default: str, pdo: int) -> str:
    return (
        f"ParameterName={name}\r\nObjectType=0x7\r\nDataType=0x{data_type:04X}\r\n"
        f"AccessType={access}\r\nDefaultValue={default}\r\nPDOMapping={pdo}\r\n\r\n"
    )


def _header(indices: list[int], extra: list[int]) -> str:
    comm = [0x1000, 0x1001, 0x1018]
    pdo = extra + [0x1400 + n for n in range(4)] + [0x1600 + n for n in range(4)]
    pdo += [0x1800 + n for n in range(4)] + [0x1A00 + n for n in range(4)]
    parts = [
        "[FileInfo]\r\nFileName=synthetic.eds\r\nFileVersion=1\r\nFileRevision=0\r\nEDSVersion=4.0\r\n"
        "Description=synthetic scale benchmark device\r\nCreationTime=09:00AM\r\nCreationDate=01-15-2025\r\n"
        "CreatedBy=bench/synthetic_eds.py\r\n\r\n",
        "[DeviceInfo]\r\nVendorName=bench\r\nVendorNumber=0x00000CA7\r\nProductName=synthetic\r\n"
        "ProductNumber=0x00000001\r\nRevisionNumber=0x00010000\r\nOrderCode=S1\r\nBaudRate_10=0\r\nBaudRate_20=0\r\n"
        "BaudRate_50=0\r\nBaudRate_125=1\r\nBaudRate_250=1\r\nBaudRate_500=1\r\nBaudRate_800=0\r\n"
        "BaudRate_1000=1\r\nSimpleBootUpMaster=0\r\nSimpleBootUpSlave=1\r\nGranularity=8\r\n"
        "DynamicChannelsSupported=0\r\nGroupMessaging=0\r\nNrOfRXPDO=4\r\nNrOfTXPDO=4\r\nLSS_Supported=1\r\n\r\n",
        "[DummyUsage]\r\n" + "".join(f"Dummy{t:04X}=0\r\n" for t in range(1, 8)) + "\r\n",
        _object_list("MandatoryObjects", comm),
        _object_list("OptionalObjects", pdo + [i for i in indices if i >= 0x6000]),
        _object_list("ManufacturerObjects", [i for i in indices if i < 0x6000]),
    ]
    return "".join(parts)


def _object_list(name: str, indices: list[int]) -> str:
    lines = [f"[{name}]", f"SupportedObjects={len(indices)}"]
    lines += [f"{n}=0x{index:04X}" for n, index in enumerate(indices, 1)]
    return "\r\n".join(lines) + "\r\n\r\n"


def _record(index: int, name: str, object_type: int, subs: Iterator[tuple[str, int, str, str, int]]) -> str:
    body = "".join(f"[{index:04X}sub{sub:X}]\r\n{_entry(*entry)}" for sub, entry in enumerate(subs))
    count = body.count("ParameterName=")
    return f"[{index:04X}]\r\nParameterName={name}\r\nObjectType=0x{object_type:X}\r\nSubNumber={count}\r\n\r\n" + body


def _communication(mapped: list[tuple[int, int]]) -> str:
    """1000h, 1001h, 1018h and 4 RPDOs/TPDOs, each mapping two of the first 32-bit VARs."""
    parts = [
        f"[1000]\r\n{_entry('Device type', 0x0007, 'ro', '0x00000000', 0)}",
        f"[1001]\r\n{_entry('Error register', 0x0005, 'ro', '0', 1)}",
    ]
    identity = [("Highest sub-index supported", 0x0005, "const", "4", 0)]
    numbers = (("Vendor-ID", "0x00000CA7"), ("Product code", "0x00000001"), ("Revision", "0x00010000"))
    identity += [(name, 0x0007, "ro", value, 0) for name, value in (*numbers, ("Serial", "0"))]
    parts.append(_record(0x1018, "Identity object", 9, iter(identity)))
    for number in range(4):
        for base, direction, cob in ((0x1400, "RPDO", 0x200), (0x1800, "TPDO", 0x180)):
            parameters = [
                ("Highest sub-index supported", 0x0005, "const", "2", 0),
                ("COB-ID", 0x0007, "rw", f"$NODEID+0x{cob + 0x100 * number:X}", 0),
                ("Transmission type", 0x0005, "rw", "0xFF", 0),
            ]
            parts.append(_record(base + number, f"{direction} communication parameter", 9, iter(parameters)))
            first = mapped[(2 * number + (base == 0x1800) * 8) % len(mapped) :][:2]
            mapping = [("Number of mapped objects", 0x0005, "rw", str(len(first)), 0)]
            mapping += [
                (f"Mapped object {n}", 0x0007, "rw", f"0x{index:04X}0020", 0) for n, (index, _) in enumerate(first, 1)
            ]
            parts.append(_record(base + 0x200 + number, f"{direction} mapping parameter", 9, iter(mapping)))
    return "".join(parts)


# Communication objects CANopenNode's CANopen.c needs besides 1000h, 1001h and 1018h.
_CANOPENNODE_INDICES = [0x1003, 0x1014, 0x1016, 0x1017]


def _canopennode_objects() -> str:
    errors = [("Number of errors", 0x0005, "rw", "0", 0)]
    errors += [(f"Standard error field {n}", 0x0007, "ro", "0", 0) for n in range(1, 9)]
    consumers = [("Highest sub-index supported", 0x0005, "ro", "4", 0)]
    consumers += [(f"Consumer heartbeat time {n}", 0x0007, "rw", "0", 0) for n in range(1, 5)]
    return "".join(
        [
            _record(0x1003, "Pre-defined error field", 8, iter(errors)),
            f"[1014]\r\n{_entry('COB-ID EMCY', 0x0007, 'ro', '$NODEID+0x80', 0)}",
            _record(0x1016, "Consumer heartbeat time", 8, iter(consumers)),
            f"[1017]\r\n{_entry('Producer heartbeat time', 0x0006, 'rw', '0', 0)}",
        ]
    )


def synthetic_eds(size: int, canopennode: bool = False) -> bytes:
    """An EDS of about `size` bytes (at least a few kB); with `canopennode`, one that passes that profile."""
    # 60 % of the indices are ARRAY/RECORD: enough sub-objects on average to fit `size` into the index range.
    average_subs = max(4, min(120, int(size / ((LAST - FIRST + 1) * 0.6 * _SUB_BYTES)) + 3))
    objects: list[str] = []
    indices: list[int] = []
    mapped: list[tuple[int, int]] = []
    total = 0
    n = 0
    while total < size:
        index = FIRST + n
        if index > LAST:
            raise SystemExit(f"synthetic_eds: {size} bytes do not fit in 0x{FIRST:04X}..0x{LAST:04X}")
        if n % 5 < 2:
            data_type, default = _VAR_TYPES[n % len(_VAR_TYPES)]
            access = _ACCESS[n % len(_ACCESS)]
            pdo = int(data_type != 0x0009 and access in ("rw", "ro", "rww", "rwr"))
            text = f"[{index:04X}]\r\n{_entry(f'Parameter {n}', data_type, access, default, pdo)}"
            if data_type == 0x0007 and access == "rw" and len(mapped) < 16:
                mapped.append((index, 32))
        else:
            count = 1 + (n * 7) % (2 * average_subs - 1)  # 1 .. 2*average-1 sub-objects after sub 0
            is_array = n % 5 == 2
            subs = [("Highest sub-index supported", 0x0005, "ro", str(count), 0)]
            for sub in range(1, count + 1):
                data_type, default = (0x0006, f"0x{sub:04X}") if is_array else _VAR_TYPES[(n + sub) % len(_VAR_TYPES)]
                access = _ACCESS[(n + (1 if is_array and canopennode else sub)) % len(_ACCESS)]
                subs.append((f"Entry {sub}", data_type, access, default, 0))
            text = _record(index, f"{'Array' if is_array else 'Record'} {n}", 8 if is_array else 9, iter(subs))
        objects.append(text)
        indices.append(index)
        total += len(text)
        n += 1
    extra = _CANOPENNODE_INDICES if canopennode else []
    communication = _communication(mapped) + (_canopennode_objects() if canopennode else "")
    return (_header(indices, extra) + communication + "".join(objects)).encode("ascii")


def parse_size(text: str) -> int:
    units = {"K": 1 << 10, "M": 1 << 20, "G": 1 << 30}
    text = text.strip().upper().removesuffix("B")
    if text and text[-1] in units:
        return int(float(text[:-1]) * units[text[-1]])
    return int(text)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("size", type=parse_size, help="about how many bytes, e.g. 5M, 50M, 200K")
    parser.add_argument("-o", "--output", type=Path, help="the file to write (default: stdout)")
    parser.add_argument("--canopennode", action="store_true", help="a file that passes lint --profile canopennode")
    args = parser.parse_args(argv)
    data = synthetic_eds(args.size, args.canopennode)
    if args.output is None:
        sys.stdout.buffer.write(data)
    else:
        args.output.write_bytes(data)
    return 0


if __name__ == "__main__":
    sys.exit(main())
