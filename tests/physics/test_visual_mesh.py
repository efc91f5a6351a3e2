""".obj models in the MuJoCo world: the real stop sign and S4blue get mesh geoms of their true
size on their bodies, collisions, mass and sensors still use the colliders, and the OpenGL camera
sees the model where the ray caster (and the colliders alone) would not."""

import mujoco
import numpy as np
import pytest
from support.corpus import CORPUS
from support.rooms import write_scene

from eyesim.core.engine import Simulation
from eyesim.physics import render, render_gl
from eyesim.physics.meshes import read_obj
from eyesim.physics.render_raycast import RayCastRenderer
from eyesim.physics.visual_mesh import COVERED_GROUP, MESH_GROUP, mesh_geoms
from eyesim.scene.loader import load_scene

STOP_SIGN = CORPUS / "NoahWMueller__Eyesim/Sims/Objects/StopSign"
S4BLUE = CORPUS / "NoahWMueller__Eyesim/Sims/Updated_Robots/S4blue.robi"


def scene_file(tmp_path, placements, extra=()):
    return write_scene(tmp_path, ["floor 2000 2000"], placements, extra=list(extra))


@pytest.fixture(scope="module")
def sim(tmp_path_factory):
    """A stop sign at (1000, 1000), its face towards -x, and S4blue at (500, 1000) facing it."""
    path = scene_file(
        tmp_path_factory.mktemp("stop"),
        ["S4blue 500 1000 0", "StopSign 1000 1000 0"],
        [f'obj "{STOP_SIGN / "stopsign.esObj"}"', f'robi "{S4BLUE}"'],
    )
    return Simulation(load_scene(path))


def world_box(model, data, geoms):
    """Lowest and highest corner (m, world) of the geoms' mesh vertices."""
    points = []
    for geom in geoms:
        mesh = model.geom_dataid[geom]
        vertices = model.mesh_vert[model.mesh_vertadr[mesh] : model.mesh_vertadr[mesh] + model.mesh_vertnum[mesh]]
        points.append(data.geom_xpos[geom] + vertices @ data.geom_xmat[geom].reshape(3, 3).T)
    points = np.concatenate(points)
    return points.min(axis=0), points.max(axis=0)


def test_the_stop_sign_gets_mesh_geoms_as_big_as_the_file_says(sim):
    model, data = sim.world.model, sim.world.data
    sign = sim.objects[0]
    assert len(sign.mesh_geoms) == 3  # its four materials have three colours
    assert (model.geom_type[sign.mesh_geoms] == mujoco.mjtGeom.mjGEOM_MESH).all()
    assert (model.geom_contype[sign.mesh_geoms] == 0).all() and (model.geom_conaffinity[sign.mesh_geoms] == 0).all()
    low, high = world_box(model, data, sign.mesh_geoms)
    file_low, file_high = read_obj(STOP_SIGN / "STOP.obj").bounds()
    scale = sign.type.scale
    # the file's Y is up, its Z forward (+x) and its x (mirrored twice) to the left (+y)
    assert np.allclose(
        high - low,
        np.array([file_high[2] - file_low[2], file_high[0] - file_low[0], file_high[1] - file_low[1]]) * scale,
        atol=1e-5,
    )  # 50 x 126 x 378 mm
    assert np.allclose(high[2], file_high[1] * scale, atol=1e-5)  # the sign stands where the file says
    assert np.allclose(
        [(low[0] + high[0]) / 2, (low[1] + high[1]) / 2],
        [1.0 + (file_low[2] + file_high[2]) / 2 * scale, 1.0 + (file_low[0] + file_high[0]) / 2 * scale],
        atol=1e-5,
    )


def test_colliders_keep_colliding_and_the_mass_is_the_declared_one(sim):
    model = sim.world.model
    sign, robot = sim.objects[0], sim.robots[0]
    assert sign.geoms and (model.geom_group[sign.geoms] == COVERED_GROUP).all()
    assert (model.geom_contype[sign.geoms] != 0).all()
    assert model.body_mass[sign.body] == pytest.approx(2.0)  # stopsign.esObj: mass 2
    assert model.body_subtreemass[robot.body] == pytest.approx(robot.type.mass, rel=1e-6)


def test_s4blue_gets_its_model_turned_as_its_robi_says(sim):
    model, data = sim.world.model, sim.world.data
    robot = sim.robots[0]
    low, high = world_box(model, data, mesh_geoms(model, robot.body))
    size = high - low
    # model S4blue.obj 0 0 0 0 90 0: the long side forward, as the robot's declared size
    assert size == pytest.approx(
        [robot.type.length / 1000, robot.type.width / 1000, robot.type.height / 1000], abs=0.003
    )
    assert low[2] == pytest.approx(0.0, abs=0.001)


def test_sensor_rays_hit_the_colliders_not_the_model(sim):
    # 35 mm beside the pole (a 3.75 mm capsule), at the height of the sign's face, which only the
    # model has: the ray PSDs and lidars use passes it; MuJoCo's ray over all geoms would not.
    model, data = sim.world.model, sim.world.data
    origin, ahead = np.array([0.6, 1.035, 0.29]), np.array([1.0, 0.0, 0.0])
    geom = np.zeros(1, dtype=np.int32)
    with_models = mujoco.mj_ray(model, data, origin, ahead, None, 1, -1, geom)
    assert int(geom[0]) in sim.objects[0].mesh_geoms and with_models == pytest.approx(0.4, abs=0.01)
    assert sim.world.ray(origin, ahead, -1) is None
    assert sim.world.ray(np.array([0.6, 1.0, 0.29]), ahead, -1) == pytest.approx(0.4 - 0.00375, abs=1e-4)


@pytest.fixture(scope="module")
def opengl():
    return render_gl.GlRenderer(render_gl.choose_backend(""))


def test_the_opengl_camera_sees_the_model_and_the_ray_caster_the_colliders(sim, opengl):
    # 400 mm in front of the sign's face and 35 mm beside its pole, looking at the face
    view = render.View((0.6, 1.035, 0.29), (1.0, 0.0, 0.0), (0.0, 0.0, 1.0), 160, 120, 60)
    gl_image = opengl.render(sim.world, view)
    cast_image = RayCastRenderer().render(sim.world, view)
    centre = (slice(54, 66), slice(74, 86))
    # the face's colour (Kd 0.82 0.85 0.83), lit head-on, where the colliders leave the empty sky
    assert (gl_image[centre].astype(int) > 150).all()
    assert (cast_image[centre] == render.BACKGROUND).all()
    assert (gl_image[:3] == render.BACKGROUND).all() and (cast_image[:3] == render.BACKGROUND).all()


def test_geom_groups_hide_the_covered_colliders_from_opengl_only():
    option = mujoco.MjvOption()
    assert option.geomgroup[MESH_GROUP] == 1 and option.geomgroup[COVERED_GROUP] == 0
