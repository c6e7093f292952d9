"""Settings every test module shares.

Hypothesis runs derandomized (the examples follow from each test's own code, not from a random seed)
and without its example database: a property test passes or fails the same way on every run and
every machine, so `make test` on a clean clone cannot fail at random. Inputs a property once found
are kept as `@example`s beside the test.
"""

from __future__ import annotations

from hypothesis import settings

settings.register_profile("cantools-od", derandomize=True, database=None)
settings.load_profile("cantools-od")
