"""Objects added from Python opt out of casting shadows (Scene.set_cast_shadows, a scene file's
"cast_shadows"): a sphere over a floor under a shadowed light darkens the floor, and no longer
once it casts none; both renderers give the same bytes either way."""

import numpy as np

import phongvk


def test_an_added_object_that_casts_no_shadow_leaves_the_floor_lit():
    scene = phongvk.Scene(96, 72)
    scene.camera = phongvk.Camera(position=(0, -4, 3), look_at=(0, 0, 0), width=96, height=72)
    scene.lights = [phongvk.Light(position=(0, 0, 4), intensity=1, shadows=True)]
    scene.render_settings.shading = "phong"  # a ray per pixel: the floor is two triangles
    scene.add(np.array([[-2, -2, 0], [2, -2, 0], [2, 2, 0], [-2, 2, 0]], np.float32), np.array([[0, 1, 2], [0, 2, 3]]))
    # A small closed tetrahedron 1 m over the floor's centre, in the light's way.
    ball = scene.add(np.array([[-0.4, -0.4, 0.8], [0.4, -0.4, 0.8], [0, 0.4, 0.8], [0, 0, 1.4]], np.float32),
                     np.array([[0, 2, 1], [0, 1, 3], [1, 2, 3], [2, 0, 3]]), closed=True)
    assert scene.casts_shadows(ball)
    gpu, cpu = phongvk.Renderer("gpu"), phongvk.Renderer("cpu")
    shadowed = gpu.render(scene)
    assert np.array_equal(shadowed, cpu.render(scene))
    scene.set_cast_shadows(ball, False)
    assert not scene.casts_shadows(ball)
    lit = gpu.render(scene)
    assert np.array_equal(lit, cpu.render(scene))
    darker = (shadowed.astype(int).sum(axis=2) < lit.astype(int).sum(axis=2)).sum()
    assert darker > 20  # the floor under the tetrahedron, lit again
    assert (shadowed.astype(int).sum(axis=2) <= lit.astype(int).sum(axis=2)).all()
