"""DCF rules (cantools_od/lint/dcf.py): DCF-only keys, UploadFile/DownloadFile, NodeID, module sections."""

from __future__ import annotations

from lintkit import messages, table_tests

VAR = "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\n"
DCF_NODE = "[DeviceComissioning]\nNodeID=5\n"

# (code, text, source, expected (line, column) of each finding)
FOUND = [
    (
        "EDS050",
        DCF_NODE + "[1F50]\nParameterName=P\nObjectType=0x2\nAccessType=rw\nDownloadFile=f.bin\n",
        "t.dcf",
        [(7, 1)],
    ),
    ("EDS050", DCF_NODE + "[1F50]\nParameterName=P\nObjectType=0x2\nUploadFile=f.bin\n", "t.dcf", [(6, 1)]),
    ("EDS051", DCF_NODE + VAR.replace("rw", "ro") + "UploadFile=speed.bin\n", "t.dcf", [(7, 1)]),
    ("EDS052", VAR + "ParameterValue=5\nDenotation=Left\n", "t.eds", [(5, 1), (6, 1)]),
    ("EDS052", "[FileInfo]\nLastEDS=device.eds\n", "t.eds", [(2, 1)]),
    ("EDS060", VAR, "t.dcf", [(1, 1)]),
    ("EDS060", "[DeviceComissioning]\nNodeName=Drive\n", "t.dcf", [(1, 1)]),
    ("EDS062", "[DeviceComissioning]\nNodeID=128\n", "t.dcf", [(2, 8)]),
    ("EDS062", "[DeviceComissioning]\nNodeID=0\n", "t.dcf", [(2, 8)]),
    ("EDS063", "[DeviceComissioning]\nNodeID=0xFF\n", "t.dcf", [(2, 8)]),
    ("EDS070", "[SupportedModules]\nNrOfEntries=2\n\n[M1ModuleInfo]\nProductName=A\n", "t.eds", [(1, 1)]),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M2ModuleInfo]\nProductName=B\n",
        "t.eds",
        [(5, 1)],
    ),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M1FixedObjects]\nNrOfEntries=2\n"
        "1=0x6000\n[M1Fixed6000]\nParameterName=X\n",
        "t.eds",
        [(6, 1)],
    ),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M1SubExtends]\nNrOfEntries=1\n1=0x6000\n",
        "t.eds",
        [(7, 1)],
    ),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[ConnectedModules]\nNrOfEntries=2\n"
        "1=1\n2=2\n",
        "t.dcf",
        [(8, 1)],
    ),
]

# (code, text, source): valid input without a finding of that code
CLEAN = [
    ("EDS050", DCF_NODE + "[1F50]\nParameterName=P\nObjectType=0x2\nAccessType=wo\nDownloadFile=f.bin\n", "t.dcf"),
    ("EDS051", DCF_NODE + "[2000]\nParameterName=P\nDataType=0x000F\nAccessType=ro\nUploadFile=f.bin\n", "t.dcf"),
    ("EDS050", DCF_NODE + VAR + "UploadFile=speed.bin\n", "t.dcf"),  # not a DOMAIN: EDS051
    ("EDS052", DCF_NODE + VAR + "ParameterValue=5\n", "t.dcf"),
    ("EDS060", DCF_NODE + VAR, "t.dcf"),
    ("EDS060", VAR, "t.eds"),
    ("EDS062", "[DeviceComissioning]\nNodeID=127\n", "t.dcf"),
    ("EDS062", "[DeviceComissioning]\nNodeID=255\n", "t.dcf"),
    ("EDS063", "[DeviceComissioning]\nNodeID=0x7F\n", "t.dcf"),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M1FixedObjects]\nNrOfEntries=1\n"
        "1=0x6000\n[M1Fixed6000]\nParameterName=X\n[ConnectedModules]\nNrOfEntries=1\n1=1\n",
        "t.dcf",
    ),
]
test_finding_location, test_no_finding, test_rule_on_a_valid_file, test_rule_documented = table_tests(
    "dcf", FOUND, CLEAN
)


def test_messages() -> None:
    assert messages("[DeviceComissioning]\nNodeID=0xFF\n", "EDS063") == ["NodeID=255: node-ID not configured"]
