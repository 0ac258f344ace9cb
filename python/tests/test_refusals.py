"""What the programs refuse, Python refuses too: the same message, as
ValueError (a bad option) or OSError (a file), and never a crash."""

import pathlib

import pytest

import rasterlab

OBJ = pathlib.Path(__file__).resolve().parents[2] / "obj"


def refused(exception, call):
    with pytest.raises(exception) as caught:
        call()
    return str(caught.value)


def test_unknown_method(programs):
    assert refused(ValueError, lambda: rasterlab.lesson02.draw(raster="fast")) == \
        programs.error("02", "--raster", "fast")


def test_unknown_method_of_lesson07(programs):
    assert refused(ValueError, lambda: rasterlab.lesson07.render(normal_map="bump")) == \
        programs.error("07", "--normal-map", "bump")


@pytest.mark.parametrize("width", [0, 16385])
def test_image_size(programs, width):
    assert refused(ValueError, lambda: rasterlab.lesson01.draw(width=width)) == \
        programs.error("01", "--width", width)


def test_missing_model(programs, tmp_path):
    missing = tmp_path / "nowhere.obj"
    assert refused(OSError, lambda: rasterlab.lesson02.draw(str(missing))) == \
        programs.error("02", "-m", missing)
    assert refused(OSError, lambda: rasterlab.load_mesh(missing)) == \
        programs.error("02", "-m", missing)


def test_malformed_model(programs, tmp_path):
    broken = tmp_path / "broken.obj"
    broken.write_text("v 0 0 0\nv 1 0 0\nf 1 2 7\n")
    assert refused(OSError, lambda: rasterlab.lesson05.render([broken])) == \
        programs.error("05", "-m", broken)


def test_a_directory_is_not_a_model(programs, tmp_path):
    assert refused(OSError, lambda: rasterlab.lesson07.render([tmp_path])) == \
        programs.error("07", "-m", tmp_path)


def test_zero_light(programs):
    assert refused(ValueError, lambda: rasterlab.lesson06.render(light=(0, 0, 0))) == \
        programs.error("06", "--light", 0, 0, 0)
    assert refused(ValueError, lambda: rasterlab.lesson02.draw(light=(0, 0, 0))) == \
        programs.error("02", "--light", 0, 0, 0)


def test_light_needs_three_numbers(programs):
    assert refused(ValueError, lambda: rasterlab.lesson05.render(light=(1, 2))) == \
        programs.error("05", "--light", 1, 2)


def test_not_finite(programs):
    message = refused(ValueError, lambda: rasterlab.Camera(eye=(0, float("nan"), 1)))
    assert message == programs.error("05", "--eye", 0, "nan", 1)


def test_unusable_camera(programs):
    assert refused(ValueError, lambda: rasterlab.lesson05.render(
        camera=rasterlab.Camera(fov=200))) == programs.error("05", "--fov", 200)
    assert refused(ValueError, lambda: rasterlab.lesson07.render(
        camera=rasterlab.Camera(eye=(0, 0, 0), target=(0, 0, 0)))) == \
        programs.error("07", "--eye", 0, 0, 0, "--target", 0, 0, 0)


def test_out_of_range_number(programs):
    assert refused(ValueError, lambda: rasterlab.lesson04.draw(scale=0)) == \
        programs.error("04", "--scale", 0)
    assert refused(ValueError, lambda: rasterlab.lesson03.zfight(near=0)) == \
        programs.error("03", "zfight", "--near", 0)


def test_wrong_types_are_type_errors():
    with pytest.raises(TypeError):
        rasterlab.lesson02.draw(width="wide")
    with pytest.raises(TypeError):
        rasterlab.lesson05.render(models=[3])


def test_too_many_models():
    with pytest.raises(ValueError, match="at most 64 models"):
        rasterlab.lesson05.render([OBJ / "crate.obj"] * 65)


def test_saving_over_an_input_is_refused(tmp_path):
    texture = tmp_path / "copy.tga"
    texture.write_bytes((OBJ / "crate_diffuse.tga").read_bytes())
    rasterlab.read_image(texture)
    with pytest.raises(OSError, match="copy.tga"):
        rasterlab.lesson01.draw(width=8, height=8).save(texture)


def test_no_models_is_not_the_default_scene():
    with pytest.raises(ValueError, match="an empty list"):
        rasterlab.lesson05.render(models=[])


@pytest.mark.parametrize("models", [b"obj/crate.obj", 3])
def test_what_a_model_is(models):
    with pytest.raises(TypeError, match="a model is a path"):
        rasterlab.lesson07.render(models)


def test_spot_options_need_a_spot_light(programs):
    assert refused(ValueError, lambda: rasterlab.lesson08.render(light_position=(1, 2, 3))) == \
        programs.error("08", "--light-position", 1, 2, 3)
    assert refused(ValueError, lambda: rasterlab.lesson08.render(cone=30)) == \
        programs.error("08", "--cone", 30)
