"""The Python module as a notebook or a script uses it: pictures byte for byte the command line's,
terms against their closed forms, the command line's messages as exceptions, the GIL released."""

import math
import os
import subprocess
import threading
import time

import numpy as np
import pytest

import illum

CLI = os.environ["ILLUM_CLI"]
DUCK = "/usr/share/assimp/models/Collada/duck.dae"
EXAMPLES = os.environ["ILLUM_EXAMPLES_DIR"]


def cli_png(tmp_path, *args):
    out = tmp_path / "cli.png"
    subprocess.run([CLI, "render", *args, "-o", str(out), "-q"], check=True)
    return out.read_bytes()


def cli_error(*args):
    r = subprocess.run([CLI, *args], capture_output=True, text=True)
    assert r.returncode == 2
    return r.stderr.strip().removeprefix("illum: error: ")


def test_built_in_scene_is_the_command_lines_picture(tmp_path):
    picture = illum.render(resolution=(160, 120), model="phong")
    assert isinstance(picture, illum.Picture)
    assert picture.shape == (120, 160, 4) and picture.dtype == np.uint8
    assert picture.png() == cli_png(tmp_path, "--resolution", "160,120", "--model", "phong")


def test_model_file_and_model_read_once_draw_the_same_bytes(tmp_path):
    model = illum.load_model(DUCK)
    assert model.triangle_count == 4212 and model.vertices.shape == (model.vertex_count, 3)
    assert model.faces.shape == (4212, 3) and model.faces.max() < model.vertex_count
    low, high = (np.array(b) for b in model.bounds)
    assert (model.vertices >= low - 1e-5).all() and (model.vertices <= high + 1e-5).all()
    by_path = illum.render(DUCK, resolution=(200, 150), camera_azimuth_angle=30)
    assert (illum.render(model, resolution=(200, 150), camera_azimuth_angle=30) == by_path).all()
    assert by_path.png() == cli_png(tmp_path, DUCK, "--resolution", "200,150", "--camera-azimuth-angle", "30")
    # A file manager's URI names the same file.
    assert (illum.render("file://" + DUCK.replace("/", "%2F").replace("%2F", "/"), resolution=(200, 150),
                         camera_azimuth_angle=30) == by_path).all()


def test_a_scene_dict_draws_as_its_file_does(tmp_path):
    import json
    path = os.path.join(EXAMPLES, "first_light.json")
    with open(path) as f:
        scene = json.load(f)
    scene["lights"][0]["diffuse"] = [1, 0.5, 0.25]  # built in code: the file's light, orange
    changed = tmp_path / "changed.json"
    changed.write_text(json.dumps(scene))
    assert illum.render(scene).png() == cli_png(tmp_path, str(changed))
    assert not (illum.render(scene) == illum.render(path)).all()


@pytest.mark.parametrize("encoding", ["linear", "srgb"])
def test_linear_values_are_what_the_bytes_encode(encoding):
    picture = illum.render(resolution=(80, 60), linear=True, encoding=encoding, samples=1)
    assert picture.dtype == np.float32 and picture.shape == (60, 80, 4)
    assert picture.display.dtype == np.uint8 and picture.display.shape == (60, 80, 4)
    assert picture._repr_png_()[:8] == b"\x89PNG\r\n\x1a\n"
    c = np.clip(np.asarray(picture)[..., :3], 0, 1)
    if encoding == "srgb":  # IEC 61966-2-1
        c = np.where(c <= 0.0031308, 12.92 * c, 1.055 * c ** (1 / 2.4) - 0.055)
    assert np.abs(np.round(c * 255) - picture.display[..., :3]).max() <= 1
    assert len(np.unique(picture.display[..., 0])) > 20  # a picture, not a flat background


def test_repr_png_is_the_png_jupyter_shows():
    picture = illum.render(resolution=(40, 30))
    png = picture._repr_png_()
    assert png[:8] == b"\x89PNG\r\n\x1a\n"
    assert int.from_bytes(png[16:20], "big") == 40 and int.from_bytes(png[20:24], "big") == 30


def test_eval_answers_the_seed_exercise_term_by_term():
    # Lambert: diffuse = kd · Ld · cos θ; Phong: specular = ks · Ls · (R·V)^n.
    t = illum.eval(model="phong", angle_nl=60, angle_rv=30, shininess=4, material_diffuse=(0.8, 0.8, 0.8),
                   material_specular=(1, 1, 1))
    assert t["diffuse"] == pytest.approx([0.4] * 3, abs=1e-4)
    assert t["specular"] == pytest.approx([math.cos(math.radians(30)) ** 4] * 3, abs=1e-4)
    assert t["RoV"] == pytest.approx(math.cos(math.radians(30)), abs=1e-4)
    # The seeds' coloured-light exercise, as `illum eval --help` gives it.
    t = illum.eval(model="phong", distance=1, angle_nl=30, angle_rv=0, light_ambient=(0.4, 0.9, 0.2),
                   light_diffuse=(0.3, 1, 1), light_specular=(1, 1, 1), material_ambient=(0.9, 0.9, 0.1),
                   material_diffuse=(0.8, 1, 0.8), material_specular=(0, 1, 0.6), shininess=2)
    c = math.cos(math.radians(30))
    assert t["ambient"] == pytest.approx([0.36, 0.81, 0.02], abs=1e-4)
    assert t["diffuse"] == pytest.approx([0.24 * c, c, 0.8 * c], abs=1e-4)
    assert t["specular"] == pytest.approx([0, 1, 0.6], abs=1e-4)


def test_eval_sweeps_give_a_dict_per_value():
    rows = illum.eval(model="lambert", angle_nl="0:90:30", material_diffuse=(1, 1, 1))
    assert [r["angle-nl"] for r in rows] == [0, 30, 60, 90]
    for r in rows:
        assert r["diffuse"][0] == pytest.approx(math.cos(math.radians(r["angle-nl"])), abs=1e-4)
    assert len(illum.eval(shininess=[1, 10, 100])) == 3


@pytest.mark.parametrize("kwargs, argv", [
    ({"size": 3}, ["render", "--size", "3"]),
    ({"model": "phnog"}, ["render", "--model", "phnog"]),
    ({"width": 0}, ["render", "--width", "0"]),
    ({"width": "wide"}, ["render", "--width", "wide"]),
])
def test_refused_options_raise_the_command_lines_message(kwargs, argv):
    with pytest.raises(illum.InputError) as e:
        illum.render(**kwargs)
    assert str(e.value) == cli_error(*argv)
    assert isinstance(e.value, ValueError)


def test_eval_refusals_are_the_command_lines_too():
    with pytest.raises(illum.InputError) as e:
        illum.eval(angle_nl=200)
    assert str(e.value) == cli_error("eval", "--angle-nl", "200")


def test_a_missing_file_is_an_input_error():
    with pytest.raises(illum.InputError, match="no such"):
        illum.render("/nonexistent/model.glb")


def test_compare_and_history_sheets_are_the_command_lines(tmp_path):
    sheet = illum.compare(rows="model=phong,blinn-phong", cols="shininess=8,64", resolution=(120, 90))
    out = tmp_path / "compare.png"
    subprocess.run([CLI, "compare", "--rows", "model=phong,blinn-phong", "--cols", "shininess=8,64", "--resolution",
                    "120,90", "-o", str(out), "-q"], check=True)
    assert sheet.png() == out.read_bytes()
    history = illum.history(DUCK, resolution=(90, 60), samples=4)
    assert history.ndim == 3 and history.shape[1] > 3 * 90


def test_progress_is_reported_and_rendering_releases_the_gil():
    fractions = []
    ticks = []
    done = threading.Event()

    def count():
        while not done.is_set():
            ticks.append(time.monotonic())
            time.sleep(0.001)

    counter = threading.Thread(target=count)
    counter.start()
    start = time.monotonic()
    # Long enough (a few tenths of a second) for the other thread to run many times while illum draws.
    picture = illum.render(renderer="path", samples=64, resolution=(160, 120), progress=fractions.append)
    end = time.monotonic()
    done.set()
    counter.join()
    assert picture.shape == (120, 160, 4)
    assert fractions and fractions == sorted(fractions) and fractions[-1] == pytest.approx(1)
    # The other thread ran while illum drew (it could not, had the GIL been held).
    assert sum(1 for t in ticks if start < t < end) > 5


def test_an_exception_in_the_progress_callback_stops_the_render():
    class Stop(Exception):
        pass

    def stop(fraction):
        raise Stop()

    with pytest.raises(Stop):
        illum.render(renderer="path", samples=64, resolution=(120, 90), progress=stop)
