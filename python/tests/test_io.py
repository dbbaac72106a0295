"""mocapfill.load / save / convert and the Scene and Clip arrays, on the shipped fixtures."""
import numpy as np
import pytest

import mocapfill


def test_bvh_loads_as_arrays(fixtures):
    scene = mocapfill.load(str(fixtures / "bvh" / "bandai_walk_normal_001_short.bvh"))
    assert scene.source_format == "bvh"
    assert scene.clip_count == 1
    clip = scene.clip(0)
    joints = scene.joint_count
    assert clip.rotations.shape == (clip.frame_count, joints, 4)
    assert clip.translations.shape == (clip.frame_count, joints, 3)
    assert clip.root_translation.shape == (clip.frame_count, 3)
    np.testing.assert_allclose(np.linalg.norm(clip.rotations, axis=2), 1.0, atol=1e-12)
    np.testing.assert_allclose(np.diff(clip.times), 1.0 / clip.rate_hz, rtol=1e-9)
    # A BVH keys every joint at every frame.
    assert all(len(k) == clip.frame_count for k in clip.rotation_keys)
    assert scene.joint_parents[0] == -1
    assert scene.rest_translations.shape == (joints, 3)
    assert scene.rest_rotations.shape == (joints, 4)


def test_glb_round_trip_keeps_the_motion(fixtures, tmp_path):
    source = mocapfill.load(str(fixtures / "bvh" / "cmu_01_01_short.bvh"))
    out = tmp_path / "cmu.glb"
    mocapfill.save(source, str(out))
    back = mocapfill.load(str(out))
    assert back.joint_names == source.joint_names
    a, b = source.clip(0), back.clip(0)
    # Rotations as float32 in the file: the same up to sign and rounding.
    dots = np.abs(np.sum(a.rotations * b.rotations, axis=2))
    worst_deg = np.degrees(2 * np.arccos(np.clip(dots, -1, 1))).max()
    print("CMU clip through .glb: worst rotation difference %.2e deg" % worst_deg)
    assert worst_deg < 1e-3
    np.testing.assert_allclose(a.root_translation, b.root_translation, atol=1e-6)


def test_convert_writes_what_load_reads(fixtures, tmp_path):
    out = tmp_path / "bandai.glb"
    mocapfill.convert(str(fixtures / "bvh" / "bandai_walk_normal_001_short.bvh"), str(out))
    assert mocapfill.load(str(out)).clip(0).frame_count == \
        mocapfill.load(str(fixtures / "bvh" / "bandai_walk_normal_001_short.bvh")).clip(0).frame_count


def test_errors_carry_the_exit_code(fixtures, tmp_path):
    with pytest.raises(mocapfill.InputError) as missing:
        mocapfill.load(str(tmp_path / "missing.bvh"))
    assert missing.value.exit_code == 2 and "missing.bvh" in str(missing.value)
    with pytest.raises(mocapfill.InputError) as bad:
        mocapfill.load(str(fixtures / "bad" / "nan_value.bvh"))
    assert "nan_value.bvh:189:" in str(bad.value)  # file:line:column
    scene = mocapfill.load(str(fixtures / "bvh" / "cmu_01_01_short.bvh"))
    with pytest.raises(mocapfill.UsageError) as usage:
        mocapfill.save(scene, str(tmp_path / "out.txt"))
    assert usage.value.exit_code == 1
    assert not (tmp_path / "out.txt").exists()
    source = tmp_path / "in.glb"
    mocapfill.save(scene, str(source))
    before = source.read_bytes()
    with pytest.raises(mocapfill.OutputError) as overwrite:
        mocapfill.convert(str(source), str(source))
    assert overwrite.value.exit_code == 4 and source.read_bytes() == before
    assert issubclass(mocapfill.InputError, mocapfill.Error)


def test_scene_from_arrays(fixtures, tmp_path):
    source = mocapfill.load(str(fixtures / "bvh" / "cmu_01_01_short.bvh"))
    built = mocapfill.Scene.from_skeleton(source.joint_names, source.joint_parents, source.rest_translations,
                                          source.rest_rotations)
    clip = source.clip(0)
    built.add_clip(mocapfill.Clip(clip.times, clip.rotations, clip.translations, clip.rotation_keys,
                                  clip.translation_keys, name="copy", rate_hz=clip.rate_hz))
    out = built.clip(0)
    np.testing.assert_allclose(out.rotations, clip.rotations, atol=1e-12)
    np.testing.assert_allclose(out.translations, clip.translations, atol=1e-12)
    mocapfill.save(built, str(tmp_path / "built.glb"))
    assert mocapfill.load(str(tmp_path / "built.glb")).joint_count == source.joint_count


def test_bad_arrays_are_usage_errors(fixtures):
    source = mocapfill.load(str(fixtures / "bvh" / "cmu_01_01_short.bvh"))
    clip = source.clip(0)
    with pytest.raises(mocapfill.UsageError, match="rotations"):
        source.add_clip(mocapfill.Clip(clip.times, clip.rotations[:, :-1, :]))
    keys = [list(k) for k in clip.rotation_keys]
    keys[3] = [clip.frame_count + 5]
    with pytest.raises(mocapfill.UsageError, match="outside"):
        source.add_clip(mocapfill.Clip(clip.times, clip.rotations, rotation_keys=keys))
    with pytest.raises(mocapfill.UsageError, match="parents"):
        mocapfill.Scene.from_skeleton(["a", "b"], [-1], np.zeros((2, 3)), np.tile([0, 0, 0, 1.0], (2, 1)))
    with pytest.raises(mocapfill.UsageError):
        source.clip(7)


def test_save_options(fixtures, tmp_path):
    scene = mocapfill.load(str(fixtures / "bvh" / "bandai_walk_normal_001_short.bvh"))
    standard = tmp_path / "standard.bvh"
    mocapfill.save(scene, str(standard), bvh_layout="standard")
    back = mocapfill.load(str(standard))
    assert back.joint_names == scene.joint_names
    assert back.clip(0).frame_count == scene.clip(0).frame_count
    for skeleton in ("skin", "mesh", "nodes"):
        mocapfill.save(scene, str(tmp_path / (skeleton + ".glb")), gltf_skeleton=skeleton)
    # The stick figure and the skin make the file larger; reading it back skips the generated
    # stick figure (it is not user content).
    sizes = {k: (tmp_path / (k + ".glb")).stat().st_size for k in ("skin", "mesh", "nodes")}
    assert sizes["nodes"] < sizes["skin"] < sizes["mesh"], sizes
    assert mocapfill.load(str(tmp_path / "mesh.glb")).mesh_count == 0
    with pytest.raises(mocapfill.UsageError, match="gltf_skeleton"):
        mocapfill.save(scene, str(tmp_path / "x.glb"), gltf_skeleton="armature")
    assert not (tmp_path / "x.glb").exists()
