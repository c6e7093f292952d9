from .ini import Entry, Scan

def setup(entry: type[Entry], /) -> None: ...

scan: Scan
