"""The AO and shadow ground truth is what it claims: its ray tests agree with the scenes'
distance fields, its directions have the stated densities, it gives the values that geometry
fixes exactly, and its sampling error at 256 rays is small beside the budgets it judges."""

from __future__ import annotations

import math

import numpy as np
import pytest

from glint.compiler.verify.references import REFERENCES
from glint.compiler.verify.references.occlusion import (
    AO_MAX_DISTANCE,
    ao_cosine_visibility,
    cone_directions,
    cosine_directions,
    shadow_disc_light,
    shadow_ray,
    stratified_disc,
)
from glint.compiler.verify.references.occlusion_cases import ao_cases, shadow_cases
from glint.compiler.verify.references.scenes import SCENES, scene


def test_registered() -> None:
    for name in ("shadow_disc_light", "shadow_ray", "ao_cosine_visibility"):
        assert name in REFERENCES


@pytest.mark.parametrize("name", sorted(SCENES))
def test_ray_hits_agree_with_sphere_tracing_the_sdf(name: str) -> None:
    # Sphere tracing the numpy SDF in float64 is an independent route to the same verdict.
    rng = np.random.default_rng(5)
    ro = rng.uniform([-3.0, 0.05, -3.0], [3.0, 3.0, 3.0], (2000, 3))
    ro = ro[scene(name).sdf(ro) > 0.05]
    rd = rng.normal(size=ro.shape)
    rd /= np.linalg.norm(rd, axis=1, keepdims=True)
    t = np.zeros(len(ro))
    hit = np.zeros(len(ro), bool)
    for _ in range(2000):
        h = scene(name).sdf(ro + rd * t[:, None])
        hit |= h < 1e-9
        t = np.where(hit | (t > 10.0), t, t + h)
    # Rays that skim a surface can still be creeping along it: leave those undecided.
    decided = hit | (t > 10.0)
    exact = scene(name).blocked(ro, rd, 10.0)
    assert decided.mean() > 0.99
    np.testing.assert_array_equal((hit & (t <= 10.0))[decided], exact[decided])


def test_directions_have_their_densities() -> None:
    axis = np.array([[0.0, 0.0, 1.0], [0.6, 0.8, 0.0]])
    alpha = math.atan(1.0 / 8.0)
    cone = cone_directions(axis, alpha, 1024)
    cos_theta = np.einsum("psk,pk->ps", cone, axis)
    np.testing.assert_allclose(np.linalg.norm(cone, axis=-1), 1.0, atol=1e-12)
    assert cos_theta.min() >= math.cos(alpha) - 1e-12
    # Uniform in solid angle: half the directions within the angle that holds half the cap.
    half = math.acos(1.0 - 0.5 * (1.0 - math.cos(alpha)))
    assert np.mean(cos_theta > math.cos(half)) == pytest.approx(0.5, abs=0.01)
    hemi = cosine_directions(axis, 1024)
    cos_n = np.einsum("psk,pk->ps", hemi, axis)
    assert cos_n.min() >= 0.0
    assert cos_n.mean() == pytest.approx(2.0 / 3.0, abs=0.005)  # E[cos θ] under cos θ / π


def test_stratified_disc_rejects_a_count_that_is_not_a_square() -> None:
    with pytest.raises(ValueError, match="perfect square"):
        stratified_disc(1, 200)
    assert np.all(np.linalg.norm(stratified_disc(3, 64), axis=-1) <= 1.0 + 1e-12)


def test_a_wall_at_the_foot_hides_half_the_cosine_weighted_sky() -> None:
    # On the ground against the cube's face, every direction toward the face enters the cube
    # at once: exactly half of the cosine-weighted hemisphere, whatever the distance.
    for distance in (0.05, AO_MAX_DISTANCE, 10.0):
        ao = ao_cosine_visibility(
            scene="box_on_plane", p=[[0.5, 0.0, 0.0]], n=[[0.0, 1.0, 0.0]], max_distance=distance
        )
        assert ao[0] == pytest.approx(0.5, abs=0.01)


def test_open_ground_and_deep_shadow() -> None:
    assert ao_cosine_visibility(scene="sphere_on_plane", p=[[3, 0, 3]], n=[[0, 1, 0]])[0] == 1.0
    up = [[0.0, 1.0, 0.0]]
    under = [[0.5, 0.0, 0.0]]  # below the sphere's side, the light straight above
    assert shadow_disc_light(scene="sphere_on_plane", ro=under, rd=up, k=8.0)[0] == 0.0
    assert shadow_ray(scene="sphere_on_plane", ro=under, rd=up)[0] == 0.0
    assert shadow_disc_light(scene="sphere_on_plane", ro=[[3, 0, 0]], rd=up, k=8.0)[0] == 1.0


def test_a_straight_edge_through_the_light_hides_half_of_it() -> None:
    # From (1.5, 0, 0) toward (-1, 1, 0) the central ray grazes the cube's top edge at
    # (0.5, 1, 0): the edge, seen from there, is a line through the middle of the disc.
    light = np.array([[-1.0, 1.0, 0.0]]) / math.sqrt(2.0)
    for k in (4.0, 8.0, 32.0):
        seen = shadow_disc_light(scene="box_on_plane", ro=[[1.5, 0.0, 0.0]], rd=light, k=k)
        assert seen[0] == pytest.approx(0.5, abs=0.01)
    # Moving the point so that the edge clears the whole disc lights it fully.
    clear = shadow_disc_light(scene="box_on_plane", ro=[[2.2, 0.0, 0.0]], rd=light, k=8.0)
    assert clear[0] == 1.0


def test_sampling_error_is_small_beside_the_budgets() -> None:
    # Eight independent jitters at 256 rays per point, over every penumbra point of the
    # reference cases: the spread between them is the ground truth's standard error.
    case = shadow_cases()[1]
    runs = np.array(
        [
            shadow_disc_light(scene=case.scene, ro=case.ro, rd=case.light, k=8.0, seed=s)
            for s in range(8)
        ]
    )
    partial = (runs.mean(0) > 0.01) & (runs.mean(0) < 0.99)
    assert partial.sum() > 50
    spread = runs[:, partial].std(axis=0, ddof=1)
    assert spread.max() < 0.02 and spread.mean() < 0.01, (spread.max(), spread.mean())
    ao = ao_cases()[0]
    ao_runs = np.array(
        [ao_cosine_visibility(scene=ao.scene, p=ao.p, n=ao.n, seed=s) for s in range(4)]
    )
    assert ao_runs.std(axis=0, ddof=1).max() < 0.03


def test_cases_are_on_the_surfaces_and_face_the_open() -> None:
    for case in shadow_cases():
        surface = scene(case.scene)
        assert len(case.ro) > 500
        assert np.abs(surface.sdf(case.ro)).max() < 1e-9
        assert np.all(case.n @ case.light > 0.0)
    for ao in ao_cases():
        assert np.all(scene(ao.scene).sdf(ao.p + 1e-4 * ao.n) > 0.0)


def test_bad_input_is_refused_with_a_message() -> None:
    with pytest.raises(KeyError, match="known: "):
        shadow_ray(scene="nowhere", ro=[[0, 0, 0]], rd=[[0, 1, 0]])
    with pytest.raises(ValueError, match="k must be positive"):
        shadow_disc_light(scene="corner", ro=[[0, 0, 0]], rd=[[0, 1, 0]], k=0.0)
    with pytest.raises(ValueError, match="max_distance"):
        ao_cosine_visibility(scene="corner", p=[[0, 0, 0]], n=[[0, 1, 0]], max_distance=0.0)
