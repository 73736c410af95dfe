"""Every error path raises the status's class with the library's sentence;
closed handles raise; bad inputs raise before C sees them."""
import numpy as np
import pytest

import modesplit as ms
from conftest import SCENES


def L():
    return ms.lib()


def test_invalid_argument_carries_the_sentence_and_status():
    with pytest.raises(ms.InvalidArgument) as e:
        ms.Surface(nx=1, ny=64)
    assert e.value.status_name == "MS_ERR_INVALID_ARGUMENT" and e.value.status == -1
    assert "nx 1" in e.value.message and "MS_ERR_INVALID_ARGUMENT" in str(e.value)
    assert isinstance(e.value, ms.Error) and isinstance(e.value, ValueError)


def test_parse_error_names_line_and_column():
    with pytest.raises(ms.ParseError) as e:
        ms.Scene.parse('{"name": "x",\n "frame_dt": }')
    assert e.value.status_name == "MS_ERR_PARSE" and ":2:" in e.value.message


def test_io_error_names_the_file(tmp_path):
    with pytest.raises(ms.IoError) as e:
        ms.Scene.load(tmp_path / "missing.json")
    assert "missing.json" in e.value.message


def test_unstable_step_is_refused_then_state_error():
    s = ms.Surface(nx=64, ny=64, dx=0.001, wave_speed=2.0, max_substeps=1)
    with pytest.raises(ms.Unstable) as e:
        s.step(1.0)
    assert e.value.status_name == "MS_ERR_UNSTABLE" and "substeps" in e.value.message.replace("sub-steps", "substeps")


def test_plugin_error_for_an_unknown_shape():
    with pytest.raises(ms.PluginError) as e:
        ms.Shape("no_such_shape_kind")
    assert "no_such_shape_kind" in e.value.message


def test_dfsph_with_the_poly6_density_kernel_is_refused():
    with pytest.raises(ms.InvalidArgument) as e:
        ms.Volume(pressure="dfsph", density_kernel="poly6")
    assert e.value.status_name == "MS_ERR_INVALID_ARGUMENT" and "poly6" in e.value.message


def test_dfsph_volume_steps():
    v = ms.Volume(pressure="dfsph")
    v.fill_box((0, 0, 0), (0.3, 1, 0.3))
    v.step(1 / 60)
    assert v.count > 0


def test_settle_leaves_the_fill_at_rest_and_refuses_a_bad_time():
    v = ms.Volume(spacing=0.05, smoothing_length=0.1)
    v.fill_box((0, 0, 0), (0.5, 0.5, 0.2))
    v.settle(0.5)
    assert v.kinetic_energy == 0.0
    with pytest.raises(ms.InvalidArgument, match="settle -1 s"):
        v.settle(-1)


def test_state_error_after_a_failed_sim_step():
    sim = ms.Sim.from_desc(volume=dict(max_substeps=1))   # a 1/60 s frame needs more
    sim.volume.fill_box((0, 0, 0), (0.3, 0.3, 0.3))
    with pytest.raises(ms.Unstable):
        sim.step(1 / 60)
    with pytest.raises(ms.StateError) as e:
        sim.step(1 / 60)
    assert "previous step failed" in e.value.message


def test_unknown_desc_field_and_enum_name():
    with pytest.raises(ms.InvalidArgument, match="no field 'wavespeed'"):
        ms.Surface(wavespeed=1.0)
    with pytest.raises(ms.InvalidArgument, match="MS_BOUNDARY_ABSORB"):
        ms.Surface(boundary="sideways")


def test_closed_handles_raise_never_crash():
    s = ms.Surface(nx=16, ny=16)
    s.close()
    s.close()  # idempotent
    for call in (lambda: s.step(0.01), lambda: s.height, lambda: s.energy,
                 lambda: s.add_drop(0, 0, 1, 1)):
        with pytest.raises(ms.Closed):
            call()
    with ms.Sim(ms.Scene.load(SCENES / "fig4c.json")) as sim:
        vol = sim.volume
    with pytest.raises(ms.Closed):
        sim.step()
    with pytest.raises(ms.Closed, match="belongs to a Sim"):
        vol.count


def test_scene_outlives_its_sims():
    sc = ms.Scene.load(SCENES / "fig3.json")
    sim = ms.Sim(sc)
    sc.close()                      # deferred: the sim still reads it
    with pytest.raises(ms.Closed):
        sc.name
    assert sc._finalizer.alive      # the C scene is still there
    sim.step()
    sim.close()
    assert not sc._finalizer.alive  # freed with its last sim


def test_a_closed_shape_lives_while_a_volume_uses_it():
    v = ms.Volume(domain_max=(0.4, 0.4, 0.4))
    v.fill_box((0, 0, 0), (0.4, 0.4, 0.1))
    ball = ms.Shape("sphere", {"radius": 0.05})
    ball.set_pose((0.2, 0.2, 0.05))
    v.add_collider(ball)
    ball.close()
    with pytest.raises(ms.Closed):
        ball.kind
    assert ball._finalizer.alive    # the volume still uses it
    v.step(1 / 60)                  # reads the shape: no use after free
    v.remove_collider(ball)
    assert not ball._finalizer.alive
    sim = ms.Sim.from_desc(volume=dict(domain_max=(0.4, 0.4, 0.4)))
    cup = ms.Shape("sphere", {"radius": 0.05})
    sim.volume.add_collider(cup)    # through a borrowed Volume
    del cup
    import gc
    gc.collect()
    sim.step(1 / 60)
    sim.close()


def _last_error_unchanged(call, exc=ms.InvalidArgument):
    """The input check raises before C: the thread's C sentence stays."""
    with pytest.raises(ms.InvalidArgument):
        ms.Surface(nx=1)            # sets a known C sentence
    before = L().ms_last_error()
    with pytest.raises(exc) as e:
        call()
    assert L().ms_last_error() == before
    return e.value


@pytest.mark.parametrize("bad, word", [
    (np.zeros((16, 15), np.float32), "shape"),
    (np.zeros((16, 16), np.float64), "dtype"),
    (np.zeros((16, 32), np.float32)[:, ::2], "contiguous"),
    ([[1.0] * 16] * 15, "shape"),
])
def test_bad_inputs_raise_before_c(bad, word):
    s = ms.Surface(nx=16, ny=16)
    s.add_drop(0.08, 0.08, 0.03, 0.01)
    h0 = s.height.copy()
    for setter in (s.set_height, s.set_speed_map, s.set_damping_map):
        err = _last_error_unchanged(lambda: setter(bad))
        assert word in err.message
    assert np.array_equal(s.height, h0)


def test_bad_particles_raise_before_c():
    v = ms.Volume()
    err = _last_error_unchanged(lambda: v.add_particles(np.zeros((4, 2), np.float32)))
    assert "shape" in err.message
    err = _last_error_unchanged(lambda: v.add_particles(np.full((4, 3), 0.5),))
    assert "dtype" in err.message
    assert v.count == 0
    v.add_particles([[0.5, 0.5, 0.5]])   # an array-like is converted
    assert v.count == 1
