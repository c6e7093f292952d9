"""Public CANopenNode v4 firmware projects that keep CANopenEditor's OD.c/OD.h beside the project file
it generated them from: the manifest of the comparison in test_real_projects.py.

Each names the repository and the commit read, the project file (XDD/XPD, or the EDS the OD.h banner
names), the folder of OD.c/OD.h and the project's own stack configuration header. The files are read
from this machine's snapshots (tests/mirrors.py) and never committed; a project whose snapshot is
absent is skipped.
"""

from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Project:
    repo: str
    commit: str
    source: str  # the project file CANopenEditor generated OD.c/OD.h from
    od_dir: str  # where its OD.c/OD.h are ("" for the root)
    stack_config: tuple[str, ...] = ()  # the project's CO_driver_target.h
    settings: str = ""  # the project's <stem>.canopennode.toml, where it needs one
    # (index, sub-index) → why ours differs from their OD.c (docs/canopennode.md gives the reasons)
    documented: dict[tuple[int, int], str] = field(default_factory=dict)
    digit_names: bool = False  # CANopenEditor v4.0 wrote '_' before a word that starts with a digit

    @property
    def key(self) -> str:
        return f"{self.repo}:{self.source}"

    def od_file(self, name: str) -> str:
        return f"{self.od_dir}/{name}" if self.od_dir else name


# Differences, each with its reason (docs/canopennode.md, "Real projects").
OCTETS_WITHOUT_BLANKS = (
    "CANopenEditor reads hex octets without blanks as one number (one byte); CiA 306: 2 digits a byte"
)
BOOLEAN_HEX = "CANopenEditor reads a BOOLEAN default other than 0/false (here 0x00) as true; 0x00 is FALSE"
RWR_RWW_SWAPPED = (
    "CANopenEditor v4.0 mapped rwr to RPDOs and rww to TPDOs (fixed in v4.1); CiA 306: rwr is read by TPDOs"
)

PROJECTS = (
    # HEAD's OD.c is older than its XDD (banner 2024-10-21, XDD 2024-11-01): the last commit where they match.
    Project("Apach200/0_F407", "6ed2ba65e038bfecf0c119dcac13ff97c60dc51c", "CANopenNode_STM32/DS301_profile.xdd",
            "CANopenNode_STM32", ("CANopenNode_STM32/CO_driver_target.h",)),
    Project("EvgenyDD/sh_gateway", "1439ea2dcd6541075fb1da035849bb592a8f607b", "app/profile.xdd", "app",
            ("common/canopendriver/CO_driver_target.h",)),
    Project("EvgenyDD/sh_node", "bded2123b8cc354c1ea1e709179bcb84ba6ea250", "app/profile.xdd", "app",
            ("common/canopendriver/CO_driver_target.h",)),
    Project("EvgenyDD/sh_node", "bded2123b8cc354c1ea1e709179bcb84ba6ea250", "ldr/profile.xdd", "ldr",
            ("common/canopendriver/CO_driver_target.h",)),
    Project("Inviz/stm32app", "4be9fa46e0c5ff647f9d0eb68c896e2b40aa93ab", "src/configs/Base.xdd", "src/configs",
            ("src/CO_driver_target.h",), digit_names=True),
    Project("MEIKO-T-ED/CANopenNode", "95930739644d9ddeb82267c5e7f50424788e59dc", "IO_Board_sim.xdd", "",
            ("example/CO_driver_target.h",)),
    Project("lv-atomi/canopen-site-firmware", "d63986e57bb2a23157725fe5f71925defa254b18",
            "user/canopen/application/DS301_profile3.xdd", "user/canopen/application",
            ("user/canopen/driver/CO_driver_target.h",),
            documented={(0x2100, 0): OCTETS_WITHOUT_BLANKS, **{(index, sub): BOOLEAN_HEX for index, subs in
                        ((0x6100, range(1, 9)), (0x6400, (1, 2)), (0x6401, (1, 2))) for sub in subs}}),
    Project("samkwok-hkclr/packaging_machine", "7e72a8620845fd203afcab50df02c6174dd0719d",
            "CANopenNode_STM32/packaging_machine.xpd", "CANopenNode_STM32", ("CANopenNode_STM32/CO_driver_target.h",)),
    Project("sudriabotik/carte_lidar_stm32", "f303b0502164e130a21a2449100b06e10952f9ea",
            "CANopenNode_STM32/DS301_profile.eds", "CANopenNode_STM32", ("CANopenNode_STM32/CO_driver_target.h",),
            settings='[stack]\npdo_attributes = "canopeneditor"\n',
            documented={(index, 0): RWR_RWW_SWAPPED for index in (*range(0x2000, 0x2008), *range(0x2100, 0x2105))}),
    Project("wdfk-prog/canopennode-rtt", "b555fe9bc33e846e1fb7d4d5bcc2923c18e8c2ec", "examples/demo_device/project.xdd",
            "examples/demo_device", ("port/rtthread/CO_driver_target.h",)),
    Project("CANopenNode/CANopenDemo", "1f16f496cf9bec459d0c86307572eac7cdbc2ebd", "demo/demoDevice.xdd", "demo"),
    Project("sicrisembay/CANopenNode_C2000_bootloader", "9fa172664ea1c64ab1bab0d7b7b998759961b426",
            "c2000_bootloader.xdd", "", ("port/CO_driver_target.h",)),
    Project("CANopenNode/CanOpenSTM32", "164931f7c4f7c4f6fabba027991a6e956df0d197",
            "CANopenNode_STM32/DS301_profile.xpd", "CANopenNode_STM32", ("CANopenNode_STM32/CO_driver_target.h",)),
    Project("CANopenNode/CANopenNode", "fcd552ef9692adf30f250f9a00e5aed44561d735", "example/DS301_profile.xpd",
            "example", ("example/CO_driver_target.h",)),
    Project("thaanstad/ESP32_CanOpenNode", "6f4e641504a90a9d322380bd453383240bff72f1", "src/DS301_profile.xpd", "src",
            ("src/CO_driver_target.h",)),
    # Later commits replace CANopenEditor's OD.c with another generator's.
    Project("catompiler/slcan_canopen", "43eabbe178520465859eb541a3678e9bff97f118", "OD.xdd", "",
            ("CO_driver_target.h",)),
    Project("x893/CANopenNode-VG015", "33749dca36462341b1d6903585c29201291f1dcf", "OD/CANbp.xdd", "OD",
            ("CO_driver_target.h",)),
    Project("zylos146/CANFuck", "e4ddc607e229d3e9b7060ee840617b969543f5ec", "linmot.xdd", "src/canopen",
            ("src/canopen/CO_driver_target.h",)),
    Project("blue515/STM32L4_FreeRTOS_CANOpen", "f520f1cdcfe2ede6404b2036fa3ee44a724b973b",
            "CANopenNode_STM32/DS301_profile.xpd", "CANopenNode_STM32", ("CANopenNode_STM32/CO_driver_target.h",)),
    # On a branch that HEAD does not reach (the README commit of the firmware upload).
    Project("twhitford27/FinalMEng", "1a8d8cd4909d2d997564f4bb9b6376f0abb0805d",
            "CANopenNode_STM32/DS301_profile.xpd", "CANopenNode_STM32", ("CANopenNode_STM32/CO_driver_target.h",)),
    Project("skpang/ESP32S3_CANOpenNode_trainer", "4f02be159b3fd86d40333458e97e38e995bdc34c",
            "ESP32S3_CO_trainer_OD/ESP32S3_CO_trainer_OD.xdd", "ESP32S3_CO_trainer_OD",
            ("ESP32_CanOpenNode/src/CO_driver_target.h",)),
    # Each OD.c is generated from the XDD of the commit before; here the XDD adds only two parameters no object uses.
    Project("x893/CanOpenNodeAT32", "d88bb6be81221cbc5e62ca9e193ce277e72fc134", "CANopenNode_AT32/DS301_profile.xdd",
            "CANopenNode_AT32", ("CANopenNode_AT32/CO_driver_target.h",)),
    Project("sicrisembay/CANopenNode_C2000_Motor", "7ccacc5f9c36106510e41fe8e385dbdf765cf804",
            "controller/controller/controller.xdd", "controller/controller",
            ("components/CANopen/CO_driver_target.h",)),
    # The master's OD of a motor vendor's STM32 example, in a folder named in Chinese ("control examples").
    Project("dmBots/dm_canopen", "f6a822d9a8f691ae3c65e1d0a8e4d22c1407ab80", "eds/dm4310_master.xdd",
            "控制例程/STM32/canopen_master/User/canopen_node/CANopenNode_STM32",
            ("控制例程/STM32/canopen_master/User/canopen_node/CANopenNode/example/CO_driver_target.h",)),
)  # fmt: skip
