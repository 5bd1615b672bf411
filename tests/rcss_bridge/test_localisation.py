"""Self-localisation from a see: the face from lines and flags, the position by the simulator's formula."""

from __future__ import annotations

import math

import numpy as np
import pytest

from rcss_bridge.landmarks import FLAGS, LINE_NORMALS
from rcss_bridge.localisation import face_from_flags, line_faces, localise, wrap
from rcss_bridge.messages import See, SeenObject
from soccer_sim.perception.localise import DEFAULT_FLAGS, localise as simulator_localise
from soccer_sim.perception.params import SeeParams


def test_the_named_flags_are_the_simulators_flags():
    named = sorted(tuple(round(v, 6) for v in p) for p in FLAGS.values())
    assert named == sorted(tuple(round(v, 6) for v in p) for p in DEFAULT_FLAGS.tolist())


def _sighting(me, face, point):
    """The exact distance and direction (relative to ``face``) of ``point`` seen from ``me``."""
    dx, dy = point[0] - me[0], point[1] - me[1]
    return math.hypot(dx, dy), wrap(math.degrees(math.atan2(dy, dx)) - face)


@pytest.mark.parametrize("me, face", [((10.0, -5.0), 30.0), ((-40.0, 20.0), -150.0), ((0.0, -37.0), 95.0)])
def test_exact_sightings_give_the_exact_fix(me, face):
    names = [n for n, p in FLAGS.items() if abs(_sighting(me, face, p)[1]) < 45][:12]
    landmarks = tuple(SeenObject(n, *_sighting(me, face, FLAGS[n]), (), ()) for n in names)
    fix = localise(See(0, landmarks, (), None, ()))
    assert fix.flags == len(names) >= 2
    assert fix.face == pytest.approx(face, abs=1e-9)
    assert fix.position == pytest.approx(np.array(me), abs=1e-9)


def test_a_line_gives_two_faces_inside_first():
    # Facing the right line squarely from inside (face 0): sight-to-normal 0 is never sent;
    # 30 degrees to its left (face 30): s = -30, reported -30 + 90 = 60.
    inside, beyond = line_faces(LINE_NORMALS[("l", "r")], 60.0)
    assert inside == pytest.approx(30.0) and beyond == pytest.approx(-150.0)


def test_the_line_decides_the_face_when_it_agrees_with_the_flags():
    me, face = (5.0, 5.0), 30.0
    names = [n for n, p in FLAGS.items() if abs(_sighting(me, face, p)[1]) < 45]
    landmarks = tuple(SeenObject(n, *_sighting(me, face, FLAGS[n]), (), ()) for n in names)
    off = tuple(SeenObject(o.name, o.distance, round(o.direction + 2.0), (), ()) for o in landmarks)  # 2 degrees off
    line = SeenObject(("l", "r"), 50.0, 60.0, (), ())
    assert localise(See(0, off, (line,), None, ())).face == pytest.approx(30.0)
    assert localise(See(0, off, (), None, ())).face == pytest.approx(28.0, abs=0.6)


def test_the_position_formula_is_the_simulators():
    """The simulator's localise and position_from_flags (through localise here) agree on the
    quantised sightings the simulator would report."""
    params = SeeParams()
    me, body = np.array([[12.3, -7.8]]), np.array([41.0])
    expected = simulator_localise(me, np.zeros((1, 2)), body, params).position[0]
    names = []
    for name, point in FLAGS.items():
        dist, rel = _sighting(me[0], body[0], point)
        if abs(rel) < params.visible_angle / 2 or dist <= params.visible_distance:
            quantised = round(math.exp(round(math.log(dist + 1e-10) / 0.01) * 0.01) / 0.1) * 0.1
            names.append(SeenObject(name, quantised, float(np.rint(rel)), (), ()))
    fix = localise(See(0, tuple(names), (), None, ()))
    # the face comes from the flags here (the simulator is given it): compare with the same face
    from soccer_sim.perception.localise import position_from_flags
    points = np.array([FLAGS[o.name] for o in names])
    same = position_from_flags(points, [o.distance for o in names], [o.direction for o in names], body[0])
    assert same == pytest.approx(expected, abs=1e-9)
    assert fix.position == pytest.approx(expected, abs=0.2)


def test_too_little_to_localise():
    assert math.isnan(face_from_flags(np.zeros((1, 2)), np.ones(1), np.zeros(1)))
    fix = localise(See(0, (), (), None, ()))
    assert fix.flags == 0 and np.all(np.isnan(fix.position))
