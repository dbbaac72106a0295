"""mocapfill.fill and the methods around it (Database, PcaModel, retarget, filter)."""
import threading
import time

import numpy as np
import pytest

import mocapfill


def angle_deg(a, b):
    dots = np.abs(np.sum(a * b, axis=-1))
    return np.degrees(2 * np.arccos(np.clip(dots, -1.0, 1.0)))


@pytest.fixture(scope="module")
def sketch(fixtures):
    return mocapfill.load(str(fixtures / "sketches" / "walk_proud_002_legs8.glb"))


def test_default_database(default_db):
    assert default_db.name == "default"
    assert default_db.clip_count >= 10 and default_db.rate_hz == 30.0
    assert default_db.frame_count > 1000 and "Hips" in default_db.joint_names


def test_fill_keeps_keys_and_fills_the_rest(sketch, default_db):
    out, report = mocapfill.fill(sketch, default_db)
    assert report["method"] == "hierarchical" and report["database"] == "default"
    assert report["key_error_max_deg"] < 0.01
    before, after = sketch.clip(0), out.clip(0)
    assert out.joint_names == sketch.joint_names and after.frame_count == before.frame_count
    keyed = [j for j, keys in enumerate(before.rotation_keys) if keys]
    worst = 0.0
    for j in keyed:
        frames = before.rotation_keys[j]
        worst = max(worst, angle_deg(after.rotations[frames, j], before.rotations[frames, j]).max())
    print("fill through Python: %d keyed joints, worst key error %.2e deg (report: %.2e)"
          % (len(keyed), worst, report["key_error_max_deg"]))
    assert worst < 0.01
    kinds = {j["joint"]: j["kind"] for j in report["joints"]}
    synthesized = [sketch.joint_names.index(n) for n, k in kinds.items() if k == "synthesized"]
    assert len(synthesized) >= 10
    # Synthesised joints move: each turns by more than 2 degrees somewhere over the clip.
    for j in synthesized:
        assert angle_deg(after.rotations[:, j], after.rotations[:1, j]).max() > 2.0, sketch.joint_names[j]


def test_fill_releases_the_gil(sketch, default_db):
    done = threading.Event()
    ticks = 0

    def run():
        mocapfill.fill(sketch, default_db, method="fragment")
        done.set()

    worker = threading.Thread(target=run)
    start = time.perf_counter()
    worker.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0.001)
    worker.join()
    elapsed = time.perf_counter() - start
    print("fill took %.3f s; the main thread ran %d times meanwhile" % (elapsed, ticks))
    # At 1 ms sleeps the main thread runs on every few ms it is let in; held, it would not run.
    assert ticks >= 0.2 * elapsed / 0.001


def test_fill_errors(sketch, default_db, fixtures):
    with pytest.raises(mocapfill.UsageError, match="method"):
        mocapfill.fill(sketch, default_db, method="magic")
    with pytest.raises(mocapfill.UsageError):
        mocapfill.fill(sketch, default_db, keep=["NoSuchJoint"])
    not_humanoid = mocapfill.Scene.from_skeleton(["a", "b"], [-1, 0], np.array([[0, 1, 0], [0, 0.5, 0.0]]),
                                                 np.tile([0, 0, 0, 1.0], (2, 1)))
    not_humanoid.add_clip(mocapfill.Clip(np.arange(3) / 30.0, np.tile([0, 0, 0, 1.0], (3, 2, 1)),
                                         rotation_keys=[[0, 2], []]))
    with pytest.raises(mocapfill.InputError) as error:
        mocapfill.fill(not_humanoid, default_db)
    assert error.value.exit_code == 2


def test_pca_model_and_hybrid(sketch, default_db, tmp_path):
    model = mocapfill.PcaModel.build(default_db, max_components=12)
    assert 1 <= model.component_count <= 12
    assert all(a >= b for a, b in zip(model.variances, model.variances[1:]))
    path = tmp_path / "walk.pca"
    model.save(str(path))
    assert mocapfill.PcaModel.open(str(path)).component_count == model.component_count
    out, report = mocapfill.fill(sketch, default_db, method="hybrid", pca=model)
    assert report["pca_model"]["components"] == model.component_count
    assert report["key_error_max_deg"] < 0.01


def test_database_save_and_open(default_db, tmp_path):
    path = tmp_path / "default.mfdb"
    default_db.save(str(path))
    reopened = mocapfill.Database.open(str(path))
    assert reopened.clip_names == default_db.clip_names and reopened.frame_count == default_db.frame_count


def test_database_with_mirrored_clips(fixtures):
    folder = str(fixtures / "default_db")
    plain = mocapfill.Database.open(folder)
    mirrored = mocapfill.Database.open(folder, mirror=True)
    assert mirrored.clip_count == 2 * plain.clip_count
    assert sorted(n for n in mirrored.clip_names if n.endswith("#mirror")) == sorted(n + "#mirror" for n in plain.clip_names)


def test_retarget_onto_another_rig(fixtures):
    motion = mocapfill.load(str(fixtures / "bvh" / "bandai_walk_normal_001_short.bvh"))
    character = mocapfill.load(str(fixtures / "rigs" / "mixamo_prefixed.bvh"))
    out = mocapfill.retarget(motion, character)
    assert out.joint_names == character.joint_names
    assert out.clip(0).frame_count == motion.clip(0).frame_count


def test_filter_gains(fixtures):
    scene = mocapfill.load(str(fixtures / "bvh" / "cmu_01_01_short.bvh"))
    same = mocapfill.filter(scene, gains=[1.0, 1.0, 1.0])
    a, b = same.clip(0).rotations, scene.clip(0).rotations
    # Unit gains give the clip back up to rounding (compared as quaternions: arccos is too coarse near 1).
    assert np.minimum(np.abs(a - b).max(axis=2), np.abs(a + b).max(axis=2)).max() < 1e-9
    smooth = mocapfill.filter(scene, gains=[0.0, 0.0])
    jerk = lambda c: np.abs(np.diff(c.rotations, n=2, axis=0)).mean()
    print("second differences: %.3e as read, %.3e with the two highest bands off"
          % (jerk(scene.clip(0)), jerk(smooth.clip(0))))
    assert jerk(smooth.clip(0)) < 0.5 * jerk(scene.clip(0))
    with pytest.raises(mocapfill.UsageError, match="joints"):
        mocapfill.filter(scene, gains=[0.0], joints=["NoSuchJoint"])


def test_run_pipeline_fills_as_the_fill_call(fixtures, sketch, default_db, tmp_path):
    """A pipeline file run from Python writes what its export node says, and its fill node gives
    the result mocapfill.fill gives with the same options; a bad override is a UsageError."""
    pipeline = str(fixtures / "pipelines" / "fill_default.json")
    out = tmp_path / "piped.glb"
    plan = mocapfill.describe_pipeline(pipeline, sets=["out.path=%s" % out])
    assert "fill" in plan and not out.exists()  # the plan runs nothing
    report = mocapfill.run_pipeline(pipeline, sets=["out.path=%s" % out, "fill.texture=false"])
    assert report["ok"] and [n["id"] for n in report["nodes"]] == ["sketch", "db", "fill", "out"]
    fill_report = next(n for n in report["nodes"] if n["id"] == "fill")["report"]
    assert fill_report["key_error_max_deg"] < 0.01
    piped = mocapfill.load(str(out)).clip(0)
    direct, _ = mocapfill.fill(sketch, default_db, texture=False)
    worst = angle_deg(piped.rotations, direct.clip(0).rotations).max()
    print("pipeline against mocapfill.fill: worst joint difference %.2e deg" % worst)
    assert worst < 1e-3
    with pytest.raises(mocapfill.UsageError, match="nosuchnode"):
        mocapfill.run_pipeline(pipeline, sets=["nosuchnode.path=x.glb"])
    assert "pca_edit" in mocapfill.pipeline_node_types()


def test_fill_takes_every_option_of_the_schema(sketch, default_db):
    """Options beyond the named arguments go through the fill's schema by name, with its checks."""
    _, few = mocapfill.fill(sketch, default_db, candidates=8, blend=1, texture=False)
    _, many = mocapfill.fill(sketch, default_db, texture=False)
    print("fragments blended: %s with blend=1, %s by default" % (
        max(f["blended"] for f in few["fragments"]), max(f["blended"] for f in many["fragments"])))
    assert max(f["blended"] for f in few["fragments"]) == 1 < max(f["blended"] for f in many["fragments"])
    with pytest.raises(mocapfill.UsageError, match=r'option "candidates": expected an integer in \[1, 1024\], got 0'):
        mocapfill.fill(sketch, default_db, candidates=0)
    with pytest.raises(mocapfill.UsageError, match="unknown option"):
        mocapfill.fill(sketch, default_db, candidate=8)
    with pytest.raises(mocapfill.UsageError, match="given twice"):
        mocapfill.fill(sketch, default_db, plant_feet=False)
