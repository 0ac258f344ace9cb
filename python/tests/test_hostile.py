"""The module against a hostile caller: objects made without __init__,
arguments of the wrong kind. Each is refused with TypeError (or the
programs' own message), never a crash."""

import pytest

import rasterlab

CLASSES = [rasterlab.Result, rasterlab.Mesh, rasterlab.Camera]


def public_names(cls):
    return [n for n in dir(cls) if not n.startswith("__")] + ["__repr__"]


@pytest.mark.parametrize("cls", CLASSES, ids=lambda c: c.__name__)
def test_every_member_refuses_an_object_made_without_init(cls):
    bare = cls.__new__(cls)
    for name in public_names(cls):
        with pytest.raises(TypeError, match="never initialised"):
            member = getattr(bare, name)
            if callable(member):
                member() if name != "save" else member("never.png")


def test_a_render_refuses_a_mesh_or_camera_made_without_init():
    with pytest.raises(TypeError, match="never initialised"):
        rasterlab.lesson05.render(rasterlab.Mesh.__new__(rasterlab.Mesh), width=8, height=8)
    with pytest.raises(TypeError, match="never initialised"):
        rasterlab.lesson05.render(camera=rasterlab.Camera.__new__(rasterlab.Camera),
                                  width=8, height=8)
