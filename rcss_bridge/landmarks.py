"""The server's named flags and lines: where each stands, in the server's absolute frame.

A ``see`` names its flags (``(f c t)``, ``(f p l c)``, ``(g r)``, ``(f b r 30)``, ...). Their
positions are the same 55 points as :func:`soccer_sim.perception.localise.field_flags` (the
simulator's own copy of rcssserver's landmarks), here by name: ``l``/``r`` the left/right
ends (x = -/+ length/2), ``t``/``b`` the top/bottom touchlines (y = -/+ width/2: the server's
y grows towards the bottom line), ``c`` the halfway line, ``g`` a goal, ``p`` a penalty box,
and the outer ring 5 m outside the lines numbered by their distance from the centre (m).

Lines (``(l l)``, ``(l r)``, ``(l t)``, ``(l b)``) carry the direction of their outward
normal from inside the pitch (:data:`LINE_NORMALS`).
"""

from __future__ import annotations

from soccer_sim.config import STANDARD_FIELD, FieldConfig
from soccer_sim.perception.localise import FLAG_MARGIN


def flag_positions(field: FieldConfig = STANDARD_FIELD) -> dict[tuple[str, ...], tuple[float, float]]:
    """Every named landmark of the pitch ``field`` by its name tokens, e.g.
    ``("f", "p", "l", "c") -> (-36.0, 0.0)`` (m, server frame, for the default pitch)."""
    hl, hw, hg = field.half_length, field.half_width, field.goal_width / 2.0
    px, py = hl - field.penalty_area_length, field.penalty_area_width / 2.0
    out: dict[tuple[str, ...], tuple[float, float]] = {
        ("f", "c"): (0.0, 0.0), ("f", "c", "t"): (0.0, -hw), ("f", "c", "b"): (0.0, hw)}
    for end, sx in (("l", -1.0), ("r", 1.0)):
        out[("f", end, "t")] = (sx * hl, -hw)
        out[("f", end, "b")] = (sx * hl, hw)
        out[("g", end)] = (sx * hl, 0.0)
        out[("f", "g", end, "t")] = (sx * hl, -hg)
        out[("f", "g", end, "b")] = (sx * hl, hg)
        out[("f", "p", end, "t")] = (sx * px, -py)
        out[("f", "p", end, "c")] = (sx * px, 0.0)
        out[("f", "p", end, "b")] = (sx * px, py)
        out[("f", end, "0")] = (sx * (hl + FLAG_MARGIN), 0.0)
        for side, sy in (("t", -1.0), ("b", 1.0)):
            for d in (10, 20, 30):
                out[("f", end, side, str(d))] = (sx * (hl + FLAG_MARGIN), sy * d)
    for side, sy in (("t", -1.0), ("b", 1.0)):
        out[("f", side, "0")] = (0.0, sy * (hw + FLAG_MARGIN))
        for end, sx in (("l", -1.0), ("r", 1.0)):
            for d in (10, 20, 30, 40, 50):
                out[("f", side, end, str(d))] = (sx * d, sy * (hw + FLAG_MARGIN))
    return out


FLAGS = flag_positions()
"""The landmarks of the default pitch (:data:`soccer_sim.config.STANDARD_FIELD`) by name (m,
server frame)."""

LINE_NORMALS = {("l", "l"): 180.0, ("l", "r"): 0.0, ("l", "t"): -90.0, ("l", "b"): 90.0}
"""Each line's outward normal seen from inside the pitch (degrees, server frame); from
beyond the line it points the other way (``visualsenderplayer.cpp``, ``sendLine``)."""
