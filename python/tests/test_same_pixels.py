"""Every lesson's render function against its program: the same arguments
give the same bytes."""

import pathlib

import numpy as np
import pytest

import rasterlab

OBJ = pathlib.Path(__file__).resolve().parents[2] / "obj"

SMALL = dict(width=160, height=120)
SIZE = ["--width", 160, "--height", 120]


def options(keywords):
    """The program's arguments for these keywords: glossy_size=16 as --glossy-size 16."""
    return [a for k, v in keywords.items() for a in ("--" + k.replace("_", "-"), v)]


def same(result, program_result):
    assert result.image.shape == program_result.image.shape
    assert np.array_equal(result.image, program_result.image)


def test_lesson00_test_card(programs):
    same(rasterlab.lesson00.test_card(), programs.image("00"))


@pytest.mark.parametrize("misread", ["byte-order", "origin"])
def test_lesson00_misread(programs, misread):
    same(rasterlab.lesson00.test_card(misread=misread, width=64, height=32),
         programs.image("00", "--misread", misread, "--width", 64, "--height", 32))


@pytest.mark.parametrize("method", ["parametric", "dda", "bresenham", "wu"])
def test_lesson01(programs, method):
    same(rasterlab.lesson01.draw(method=method, **SMALL),
         programs.image("01", "--method", method, *SIZE))


@pytest.mark.parametrize("raster", ["scanline", "bbox", "edge"])
def test_lesson02(programs, raster):
    same(rasterlab.lesson02.draw(raster=raster, **SMALL),
         programs.image("02", "--raster", raster, *SIZE))


@pytest.mark.parametrize("flag", ["test_image", "overdraw", "owners", "no_cull"])
def test_lesson02_pictures(programs, flag):
    same(rasterlab.lesson02.draw(raster="bbox", **{flag: True}, **SMALL),
         programs.image("02", "--raster", "bbox", "--" + flag.replace("_", "-"), *SIZE))


def test_lesson02_model_and_light(programs):
    mesh = rasterlab.load_mesh(OBJ / "rock.obj")
    same(rasterlab.lesson02.draw(mesh, light=(1, 0, 0.5), **SMALL),
         programs.image("02", "-m", mesh.path, "--light", 1, 0, 0.5, *SIZE))


@pytest.mark.parametrize("hsr", ["painter", "bsp", "zbuffer"])
@pytest.mark.parametrize("scene", ["models", "sticks", "soup"])
def test_lesson03(programs, hsr, scene):
    same(rasterlab.lesson03.render(hsr=hsr, scene=scene, **SMALL),
         programs.image("03", "--hsr", hsr, "--scene", scene, *SIZE))


@pytest.mark.parametrize("fmt", ["float-z", "fixed16", "log"])
def test_lesson03_zfight(programs, fmt):
    same(rasterlab.lesson03.zfight(format=fmt, **SMALL),
         programs.image("03", *SIZE, "zfight", "--format", fmt))


@pytest.mark.parametrize("filter_", ["nearest", "bilinear", "trilinear"])
@pytest.mark.parametrize("wrap", ["repeat", "mirror", "clamp", "border"])
def test_lesson04(programs, filter_, wrap):
    same(rasterlab.lesson04.draw(filter=filter_, wrap=wrap, uv_scale=2.5, uv_offset=-0.3,
                                 **SMALL),
         programs.image("04", "--filter", filter_, "--wrap", wrap, "--uv-scale", 2.5,
                        "--uv-offset", -0.3, *SIZE))


def test_lesson04_turn_scale_no_light(programs):
    same(rasterlab.lesson04.draw(turn=(10, 80), scale=0.7, no_light=True, **SMALL),
         programs.image("04", "--turn", 10, 80, "--scale", 0.7, "--no-light", *SIZE))


@pytest.mark.parametrize("clip", ["none", "near", "guard-band", "all"])
@pytest.mark.parametrize("interpolation", ["affine", "perspective"])
def test_lesson05(programs, clip, interpolation):
    camera = rasterlab.Camera(eye=(0.5, 0.4, 1.2), target=(0, 0.3, 0), near=0.05)
    same(rasterlab.lesson05.render(camera=camera, clip=clip, interpolation=interpolation,
                                   **SMALL),
         programs.image("05", "--clip", clip, "--interpolation", interpolation,
                        "--eye", 0.5, 0.4, 1.2, "--target", 0, 0.3, 0, "--near", 0.05, *SIZE))


def test_lesson05_models_lod_filter(programs):
    globe = str(OBJ / "globe.obj")
    same(rasterlab.lesson05.render([globe], rasterlab.Camera(fov=30), lod="triangle",
                                   filter="bilinear", no_light=True, **SMALL),
         programs.image("05", "-m", globe, "--fov", 30, "--lod", "triangle", "--filter",
                        "bilinear", "--no-light", *SIZE))


@pytest.mark.parametrize("shading", ["flat", "gouraud", "phong", "blinn-phong"])
def test_lesson06(programs, shading):
    same(rasterlab.lesson06.render(shading=shading, **SMALL),
         programs.image("06", "--shading", shading, *SIZE))


def test_lesson06_options(programs):
    same(rasterlab.lesson06.render(weighting="area", shininess=5, naive=True, one_light=True,
                                   light=(-1, 1, 0.2), **SMALL),
         programs.image("06", "--weighting", "area", "--shininess", 5, "--naive",
                        "--one-light", "--light", -1, 1, 0.2, *SIZE))


@pytest.mark.parametrize("normal_map", ["tangent", "object", "none"])
@pytest.mark.parametrize("tangents", ["face", "vertex", "split"])
def test_lesson07(programs, normal_map, tangents):
    same(rasterlab.lesson07.render(normal_map=normal_map, tangents=tangents, **SMALL),
         programs.image("07", "--normal-map", normal_map, "--tangents", tangents, *SIZE))


def test_lesson07_options(programs):
    torus = rasterlab.load_mesh(str(OBJ / "torus.obj"))
    same(rasterlab.lesson07.render([torus], specular="phong", filter="nearest", naive=True,
                                   **SMALL),
         programs.image("07", "-m", torus.path, "--specular", "phong", "--filter", "nearest",
                        "--naive", *SIZE))


def test_lesson07_default_picture(programs):
    """rasterlab.lesson07.render() with no arguments draws the program's own
    default picture (800 x 800)."""
    same(rasterlab.lesson07.render(), programs.image("07"))


@pytest.mark.parametrize("filter_", ["hard", "pcf2", "poisson"])
@pytest.mark.parametrize("light_type", ["directional", "spot"])
def test_lesson08(programs, filter_, light_type):
    same(rasterlab.lesson08.render(filter=filter_, light_type=light_type, shadow_map_size=256,
                                   **SMALL),
         programs.image("08", "--filter", filter_, "--light-type", light_type,
                        "--shadow-map-size", 256, *SIZE))


def test_lesson08_options(programs):
    same(rasterlab.lesson08.render(light_type="spot", light_position=(2, 3, 2), cone=40,
                                   bias=0.001, slope_bias=2, normal_offset=0, fit="scene",
                                   map_faces="back", texture_filter="bilinear", one_light=True,
                                   shadow_map_size=300, **SMALL),
         programs.image("08", "--light-type", "spot", "--light-position", 2, 3, 2, "--cone",
                        40, "--bias", 0.001, "--slope-bias", 2, "--normal-offset", 0, "--fit",
                        "scene", "--map-faces", "back", "--texture-filter", "bilinear",
                        "--one-light", "--shadow-map-size", 300, *SIZE))


def test_lesson08_shadow_map_picture(programs):
    same(rasterlab.lesson08.render(show="shadow-map", shadow_map_size=128, **SMALL),
         programs.image("08", "--show", "shadow-map", "--shadow-map-size", 128, *SIZE))


def test_lesson08_unshadowed(programs):
    same(rasterlab.lesson08.render(show="unshadowed", one_light=True, **SMALL),
         programs.image("08", "--show", "unshadowed", "--one-light", *SIZE))



def test_lesson09_default(programs):
    same(rasterlab.lesson09.render(map_size=64, **SMALL),
         programs.image("09", "--map-size", 64, *SIZE))


def test_lesson09_glass_latlong_studio_bytes(programs):
    same(rasterlab.lesson09.render(environment="studio", map="latlong", map_size=32,
                                   filter="trilinear", material="glass", tone_map="reinhard",
                                   exposure=1.5, frame_store="bytes", normal_map="none",
                                   skybox=False, **SMALL),
         programs.image("09", "--environment", "studio", "--map", "latlong", "--map-size", 32,
                        "--filter", "trilinear", "--material", "glass", "--tone-map",
                        "reinhard", "--exposure", 1.5, "--frame-store", "bytes", "--normal-map",
                        "none", "--no-skybox",
                        *SIZE))


@pytest.mark.parametrize("irradiance", ["sh2", "convolved", "monte-carlo"])
def test_lesson09_diffuse(programs, irradiance):
    # Rays only where Monte Carlo casts them (the programs refuse --samples elsewhere).
    rays = {"samples": 8} if irradiance == "monte-carlo" else {}
    same(rasterlab.lesson09.render(material="diffuse", irradiance=irradiance, map_size=32, **rays,
                                   **SMALL),
         programs.image("09", "--material", "diffuse", "--irradiance", irradiance,
                        *options(rays), "--map-size", 32, *SIZE))


@pytest.mark.parametrize("glossy", ["split-sum", "monte-carlo"])
def test_lesson09_glossy(programs, glossy):
    # Each way with the options it reads: the blurred maps' for the split
    # sum, rays for Monte Carlo (the programs refuse the others).
    own = ({"lookup": "mirror", "glossy_levels": 3, "glossy_size": 16, "glossy_samples": 8}
           if glossy == "split-sum" else {"samples": 4})
    same(rasterlab.lesson09.render(material="plastic", roughness=0.6, glossy=glossy, **own,
                                   multiple_scattering=False, map_size=32, filter="trilinear",
                                   **SMALL),
         programs.image("09", "--material", "plastic", "--roughness", 0.6, "--glossy", glossy,
                        *options(own), "--single-scatter", "--map-size", 32,
                        "--filter", "trilinear", *SIZE))


def test_lesson09_white_metal(programs):
    same(rasterlab.lesson09.render(environment="white", material="rough-metal", metal=[1, 1, 1],
                                   roughness=1, map_size=16, glossy_size=16, **SMALL),
         programs.image("09", "--environment", "white", "--material", "rough-metal", "--metal",
                        1, 1, 1, "--roughness", 1, "--map-size", 16, "--glossy-size", 16, *SIZE))


def test_lesson10_default(programs):
    same(rasterlab.lesson10.render(**SMALL), programs.image("10", *SIZE))


@pytest.mark.parametrize("ao", ["crytek", "hemisphere", "baked"])
def test_lesson10_methods(programs, ao):
    # Baked rays are neither blurred nor turned (the programs refuse both there).
    screen = {} if ao == "baked" else {"blur": 1}
    turned = [] if ao == "baked" else ["--no-rotation"]
    same(rasterlab.lesson10.render(ao=ao, samples=8, radius=0.8, **screen,
                                   rotation=ao == "baked", show="ao", **SMALL),
         programs.image("10", "--ao", ao, "--samples", 8, "--radius", 0.8, *options(screen),
                        *turned, "--show", "ao", *SIZE))


def test_lesson10_direct_light_under_an_environment(programs):
    # The light's direction still reaches the direct light shown alone.
    same(rasterlab.lesson10.render(environment="sky", show="direct", light=(1, 2, 3), **SMALL),
         programs.image("10", "--environment", "sky", "--show", "direct", "--light", 1, 2, 3,
                        *SIZE))


def test_lesson10_gbuffer_depth(programs):
    same(rasterlab.lesson10.render(show="depth", normal_map="none", **SMALL),
         programs.image("10", "--show", "depth", "--normal-map", "none", *SIZE))


@pytest.mark.parametrize("aa", ["none", "ssaa", "msaa", "post"])
def test_lesson11(programs, aa):
    extra = {"ssaa": ["--samples", 4, "--pattern", "rotated"], "msaa": ["--shade-at", "centre"]}
    keywords = {"ssaa": {"samples": 4, "pattern": "rotated"}, "msaa": {"shade_at": "centre"}}
    same(rasterlab.lesson11.render(aa=aa, **keywords.get(aa, {}), **SMALL),
         programs.image("11", "--aa", aa, *extra.get(aa, []), *SIZE))


def test_lesson11_orbit_and_the_encoded_resolve(programs):
    same(rasterlab.lesson11.render(orbit=0.5, resolve_encoded=True, **SMALL),
         programs.image("11", "--orbit", 0.5, "--resolve-encoded", *SIZE))


def test_lesson11_tone_map(programs):
    same(rasterlab.lesson11.render(tone_map="before-resolve", exposure=3, **SMALL),
         programs.image("11", "--tone-map", "before-resolve", "--exposure", 3, *SIZE))


def test_lesson10_environment(programs):
    same(rasterlab.lesson10.render(environment="studio", **SMALL),
         programs.image("10", "--environment", "studio", *SIZE))


@pytest.mark.parametrize("threads", [1, 2])
def test_lesson12(programs, threads):
    same(rasterlab.lesson12.render(frames=3, threads=threads, tile_size=32, **SMALL),
         programs.image("12", "--frames", 3, "--threads", threads, "--tile-size", 32,
                        "--no-peer", *SIZE))


def test_lesson12_options(programs):
    same(rasterlab.lesson12.render(normal_map="object", filter="bilinear", naive=True,
                                   frames=1, **SMALL),
         programs.image("12", "--normal-map", "object", "--filter", "bilinear", "--naive",
                        "--frames", 1, "--no-peer", *SIZE))
