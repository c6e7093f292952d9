"""`run_each`, the runner of `lint`, `fmt --check` and `diff` over many files: results in the order given, the
costliest items started first."""

from __future__ import annotations

import os
import time

from cantools_od.cli.batch import SMALL_WORK, file_size, run_each


def _started(item: int) -> tuple[int, float]:
    """The item and when its work began; each takes a while, so that a third item waits for a free process."""
    began = time.monotonic()
    time.sleep(0.3)
    return item, began


def test_results_keep_the_given_order_and_the_costliest_start_first() -> None:
    items = [1, 2, 3, 4, 50, 60]
    results = run_each(_started, items, jobs=2, cost=lambda item: item)
    assert [item for item, _ in results] == items
    began = dict(results)
    assert max(began[50], began[60]) < min(began[i] for i in (1, 2, 3, 4)) - 0.15, began


def test_one_job_runs_here_in_order() -> None:
    assert [item for item, _ in run_each(_started, [3, 1, 2], jobs=1, cost=lambda item: item)] == [3, 1, 2]


def test_file_size_of_what_cannot_be_read_is_nothing() -> None:
    assert file_size("/nonexistent/device.eds") == 0
    assert file_size("bad\0name.eds") == 0


def _pid(item: int) -> int:
    return os.getpid()


def test_by_default_small_work_stays_in_this_process() -> None:
    """Starting processes would cost more than they save: under SMALL_WORK in all, none is started by default."""
    here = os.getpid()
    assert set(run_each(_pid, [1, 2, 3], jobs=None, cost=lambda item: SMALL_WORK // 4)) == {here}
    assert here not in run_each(_pid, [1, 2, 3], jobs=None, cost=lambda item: SMALL_WORK)  # enough work for processes
    assert here not in run_each(_pid, [1, 2], jobs=2, cost=lambda item: 1)  # --jobs given: as asked


def test_batches_start_with_the_costliest_and_stay_small() -> None:
    """Items travel to the processes in batches (a round trip each): never more than an eighth of a process's
    share of the items or of the cost, the costliest first, every item once."""
    from cantools_od.cli.batch import _batches

    sizes = [5] * 90 + [400, 300, 10, 10, 10, 10, 1000]
    batches = _batches(len(sizes), 2, sizes)
    assert sorted(i for batch in batches for i in batch) == list(range(len(sizes)))
    assert [sizes[i] for i in batches[0]] == [1000] and [sizes[i] for i in batches[1]] == [400]
    most, limit = len(sizes) // 16, sum(sizes) // 16
    assert all(len(batch) <= most and sum(sizes[i] for i in batch[:-1]) < limit for batch in batches)
    assert len(batches) < len(sizes) // 2  # the small ones share round trips
    assert _batches(len(sizes), 2, None) == [[i] for i in range(len(sizes))]
