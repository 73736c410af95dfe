"""1000 create/step/destroy cycles of a Sim: resident memory does not grow."""
import gc
import os

import pytest

import modesplit as ms


def rss_bytes():
    with open("/proc/self/statm") as f:
        return int(f.read().split()[1]) * os.sysconf("SC_PAGE_SIZE")


def cycle():
    with ms.Sim.from_desc(volume=dict(domain_max=(0.4, 0.4, 0.3), spacing=0.04,
                                      smoothing_length=0.08),
                          surface=dict(nx=64, ny=64, dx=0.4 / 64), field=(16, 16)) as sim:
        sim.volume.fill_box((0, 0, 0), (0.2, 0.4, 0.2))
        sim.surface.add_drop(0.3, 0.2, 0.03, 0.005)
        sim.step(1 / 60)
        sim.step(1 / 60)
        assert sim.height.shape == (64, 64)
        return sim.stats()["bytes"]


@pytest.mark.no_asan
def test_thousand_cycles_do_not_grow_rss():
    per_sim = cycle()
    for _ in range(100):         # warm up allocator pools and caches
        cycle()
    gc.collect()
    start = rss_bytes()
    for _ in range(1000):
        cycle()
    gc.collect()
    grown = rss_bytes() - start
    # a sim leaked per cycle would add 1000 x per_sim (hundreds of MiB);
    # 4 MiB is allocator noise (also a leak of ~4 KiB per cycle fails)
    assert per_sim > 100_000
    assert grown < 4 * 2**20, "RSS grew %.1f MiB over 1000 cycles (a sim holds %.1f MiB)" % (
        grown / 2**20, per_sim / 2**20)
