"""What the programs refuse, Python refuses too: the same message, as
ValueError (a bad option) or OSError (a file), and never a crash."""

import os
import pathlib
import re
import shutil

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


# Options that would change nothing: refused with the program's message, not
# ignored (the picture was the same as without them). Each pair: the call's
# keywords, and the program's arguments.
UNUSED = [
    ("09", dict(material="mirror", roughness=0.9), ["--material", "mirror", "--roughness", 0.9]),
    ("09", dict(material="glass", metal=(1, 1, 1)), ["--material", "glass", "--metal", 1, 1, 1]),
    ("09", dict(material="plastic", metal=(1, 1, 1)),
     ["--material", "plastic", "--metal", 1, 1, 1]),
    ("09", dict(samples=16), ["--samples", 16]),
    ("09", dict(glossy="monte-carlo", glossy_levels=3),
     ["--glossy", "monte-carlo", "--glossy-levels", 3]),
    ("09", dict(glossy="monte-carlo", lookup="mirror"),
     ["--glossy", "monte-carlo", "--lookup", "mirror"]),
    ("09", dict(material="mirror", irradiance="sh3"), ["--material", "mirror", "--irradiance", "sh3"]),
    ("09", dict(material="glass", multiple_scattering=False),
     ["--material", "glass", "--single-scatter"]),
    ("10", dict(ao="none", radius=3), ["--ao", "none", "--radius", 3]),
    ("10", dict(ao="none", samples=64), ["--ao", "none", "--samples", 64]),
    ("10", dict(ao="baked", blur=4), ["--ao", "baked", "--blur", 4]),
    ("10", dict(ao="baked", rotation=False), ["--ao", "baked", "--no-rotation"]),
    ("10", dict(environment="sky", light=(1, 1, 1)), ["--environment", "sky", "--light", 1, 1, 1]),
    ("10", dict(show="albedo", radius=3), ["--show", "albedo", "--radius", 3]),
    ("10", dict(show="depth", light=(1, 1, 1)), ["--show", "depth", "--light", 1, 1, 1]),
    ("09", dict(material="rough-metal", multiple_scattering=False, irradiance="sh3"),
     ["--material", "rough-metal", "--single-scatter", "--irradiance", "sh3"]),
    ("11", dict(aa="ssaa", samples=1), ["--aa", "ssaa", "--samples", 1]),
    ("11", dict(aa="none", resolve_encoded=True), ["--aa", "none", "--resolve-encoded"]),
    ("11", dict(aa="post", resolve="tent"), ["--aa", "post", "--resolve", "tent"]),
    ("11", dict(aa="none", pattern="grid"), ["--aa", "none", "--pattern", "grid"]),
]


@pytest.mark.parametrize("lesson, keywords, arguments", UNUSED,
                         ids=[" ".join(map(str, a)) for _, _, a in UNUSED])
def test_an_option_that_changes_nothing_is_refused(programs, lesson, keywords, arguments):
    render = getattr(rasterlab, f"lesson{lesson}").render
    message = refused(ValueError, lambda: render(width=64, height=48, **keywords))
    assert message == programs.error(lesson, "--width", 64, "--height", 48, *arguments)
    assert message.startswith("--"), message  # it names the option


CORPUS = pathlib.Path(__file__).resolve().parents[2] / "tests" / "robustness" / "corpus"


@pytest.mark.parametrize("lesson", ["09", "10"])
@pytest.mark.parametrize("name", ["huge_latlong.hdr", "wrapped_resolution.hdr"])
def test_an_environment_file_past_the_cap_or_with_a_wrapped_size(programs, lesson, name):
    # Refused from the header before a texel is decoded (a 16384x8192 file
    # was decoded whole: 150 s and 3.6 GB), as the programs refuse it.
    hdr = CORPUS / name
    render = getattr(rasterlab, f"lesson{lesson}").render
    assert refused(OSError, lambda: render(environment=hdr, width=16, height=16)) == \
        programs.error(lesson, "--width", 16, "--height", 16, "--environment", hdr)


@pytest.mark.parametrize("environment", [42, b"sky", None])
def test_what_an_environment_is(environment):
    with pytest.raises(TypeError, match="environment: a name .* or the path of a lat-long .hdr"):
        rasterlab.lesson09.render(environment=environment, width=16, height=16)


# --- paths -------------------------------------------------------------------

def test_a_path_that_is_not_utf8_is_named_in_the_message(programs, tmp_path):
    # A file name that is not UTF-8, as a str (os.fsdecode) and as bytes. The
    # message was empty (PyErr_SetString could not decode it); now it is the
    # program's, its bytes shown as \xff escapes.
    missing = tmp_path / os.fsdecode(b"\xff.obj")
    expected = programs.error("02", "-m", missing)
    assert expected == f"{tmp_path}/\\xff.obj: no such file"
    assert refused(OSError, lambda: rasterlab.load_mesh(missing)) == expected
    assert refused(OSError, lambda: rasterlab.load_mesh(os.fsencode(missing))) == expected
    assert refused(OSError, lambda: rasterlab.lesson02.draw(missing)) == expected
    assert refused(OSError, lambda: rasterlab.lesson05.render([str(missing)])) == \
        programs.error("05", "-m", missing)
    image = tmp_path / os.fsdecode(b"\xff.png")
    assert refused(OSError, lambda: rasterlab.read_image(os.fsencode(image))).startswith(
        f"{tmp_path}/\\xff.png: cannot open for reading")


def test_a_model_whose_path_is_not_utf8_loads_and_gives_its_path_back(tmp_path):
    folder = tmp_path / os.fsdecode(b"\xe9t\xe9")  # Latin-1 "ete", not UTF-8
    folder.mkdir()
    for name in ("crate.obj", "crate.mtl", "crate_nm_tangent.tga", "crate_spec.tga"):
        shutil.copy(OBJ / name, folder)  # crate_diffuse.tga missing: a warning naming it
    crate = rasterlab.load_mesh(folder / "crate.obj")
    assert crate.path == str(folder / "crate.obj")  # os.fsdecode's str: the same file
    assert rasterlab.load_mesh(crate.path).faces.shape == crate.faces.shape
    assert "\\xe9t\\xe9" in repr(crate)
    r = rasterlab.lesson04.draw(crate, width=16, height=16)
    assert r.warnings and "\\xe9t\\xe9/crate_diffuse.tga" in r.warnings[0]
    r.save(folder / "out.png")
    assert (folder / "out.png").stat().st_size > 0


def test_an_empty_path_is_no_such_file(programs):
    # load_mesh('') said "filesystem error: cannot make absolute path".
    assert refused(OSError, lambda: rasterlab.load_mesh("")) == programs.error("02", "-m", "")


@pytest.mark.parametrize("call, keyword", [
    (lambda p: rasterlab.load_mesh(p), "path"),
    (lambda p: rasterlab.read_image(p), "path"),
    (lambda p: rasterlab.lesson01.draw(width=8, height=8).save(p), "path"),
    (lambda p: rasterlab.lesson01.draw(p), "model"),
    (lambda p: rasterlab.lesson05.render([p]), "models"),
], ids=["load_mesh", "read_image", "save", "model", "models"])
def test_a_path_with_a_nul_names_the_nul(tmp_path, call, keyword):
    # It said "Unable to cast Python instance", or listed the signatures.
    path = str(tmp_path / "a\0b.obj")
    assert refused(ValueError, lambda: call(path)) == \
        f"{keyword}: {path!r} has a NUL character in it, which no file name can hold"


@pytest.mark.parametrize("output", ["/dev/null", "folder", "folder/", ""])
def test_save_checks_its_path_as_the_programs_check_theirs(programs, tmp_path, output):
    # save('/dev/null') and save('folder/') said "unknown image extension ''".
    (tmp_path / "folder").mkdir()
    path = output if output in ("/dev/null", "") else str(tmp_path / output)
    r = rasterlab.lesson01.draw(width=8, height=8)
    assert refused(OSError, lambda: r.save(path)) == \
        programs.error("01", "--width", 8, "--height", 8, output=path)


# --- numbers -------------------------------------------------------------------

FUNCTIONS = {
    "lesson00.test_card": rasterlab.lesson00.test_card, "lesson01.draw": rasterlab.lesson01.draw,
    "lesson02.draw": rasterlab.lesson02.draw, "lesson03.render": rasterlab.lesson03.render,
    "lesson03.zfight": rasterlab.lesson03.zfight, "lesson04.draw": rasterlab.lesson04.draw,
    "lesson05.render": rasterlab.lesson05.render, "lesson06.render": rasterlab.lesson06.render,
    "lesson07.render": rasterlab.lesson07.render, "lesson08.render": rasterlab.lesson08.render,
    "lesson12.render": rasterlab.lesson12.render, "Camera": rasterlab.Camera,
}


def numeric_keywords(function):
    """The keywords a function's signature (as pybind11 writes it) gives as
    numbers: int, float, or a list of floats."""
    doc = function.__init__.__doc__ if isinstance(function, type) else function.__doc__
    signature = doc.splitlines()[0]
    return re.findall(r"(\w+): (int|float|List\[float\]|Optional\[List\[float\]\]|"
                      r"Optional\[float\])", signature)


NUMERIC = [(name, keyword, kind) for name, f in FUNCTIONS.items()
           for keyword, kind in numeric_keywords(f)]


def test_every_numeric_keyword_is_found():
    # The signatures' parse finds them all, so that the next test covers
    # every one: lesson 08's nine (light to normal_offset), 51 in all.
    assert [k for name, k, _ in NUMERIC if name == "lesson08.render"] == [
        "light", "width", "height", "light_position", "cone", "shadow_map_size", "bias",
        "slope_bias", "normal_offset"]
    assert len(NUMERIC) == 51


@pytest.mark.parametrize("name, keyword, kind", NUMERIC, ids=[f"{n}-{k}" for n, k, _ in NUMERIC])
@pytest.mark.parametrize("flag", [True, False])
def test_a_bool_is_not_a_number(name, keyword, kind, flag):
    function = FUNCTIONS[name]
    # width=True drew a 1x1 picture: a bool is an int to Python.
    value = [flag, 0.5, 1.0] if "List" in kind else flag
    assert refused(TypeError, lambda: function(**{keyword: value})) == \
        f"{keyword}: expected a number, not the bool {flag}"


def test_frames_times_pixels_over_the_cap(programs):
    assert refused(ValueError, lambda: rasterlab.lesson12.render(
        width=16384, height=16384, frames=1000)) == \
        programs.error("12", "--width", 16384, "--height", 16384, "--frames", 1000, "--no-peer")
