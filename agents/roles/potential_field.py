"""The potential field that places supporting players, after "Dynamic multi-robot
coordination" (Vail and Veloso): a sum of simple terms, each encoding one piece of soccer
sense, each zero or linear away from where it acts, so that its gradient is bounded by its
weight (per metre) and terms interact only where they overlap. A supporter moves down the
field's gradient (the paper samples nearby points for the slope; here it is analytic).

Every term takes ``points`` (k, 2) in the team frame (metres) and returns ``(potential (k,),
gradient (k, 2))``, the gradient with respect to each player's own position; potentials are
in "metres of anchor distance" (a weight of 1 per metre is as bad as standing a metre
farther from the formation target). All terms are numba-compiled, vectorised over the
players, and callable from Python; they, the whole field (:func:`supporter_field`, with
:func:`supporter_sides`) and the step down it (:func:`descend`) live in the kernel module
:mod:`agents.roles.field_terms` and are importable from here too (their weights, reaches and
distances are :class:`~agents.roles.field_params.FieldParams`). ``w`` is the term's weight,
``r`` its reach (m).

====================  ========================================================================
term                  potential
====================  ========================================================================
:func:`walls`         ``w * max(0, 1 - d / r)`` summed over the two touchlines and two goal
                      lines, ``d`` the (signed) distance to the line: a linear push inwards
:func:`own_area`      ``w * max(0, 1 - s / r)``, ``s`` the signed distance to our penalty area
                      (negative inside): supporters keep out of the goalkeeper's area, and
                      deep inside the push out stays on
:func:`teammates`     ``w * max(0, 1 - |p - q| / r)`` summed over the other players ``q``
:func:`ball_distance` ``w * huber(|p - b| - d_eq)``: an equilibrium distance from the ball ``b``
:func:`forward_bias`  ``w * max(0, b_x + o - p_x)``: offensive supporters at least ``o`` metres
                      ahead of the ball
:func:`defensive_bias` ``w * max(0, p_x - (b_x - o))``: defensive supporters at least ``o``
                      metres goal-side of the ball
:func:`corridor_clear` ``w * max(0, 1 - c / r)``, ``c`` the distance to the segment from the ball
                      to the opponents' goal: offensive supporters leave the shooting lane open
:func:`corridor_block` ``w * huber(c')``, ``c'`` the distance to the segment from the ball to our
                      goal: defensive supporters stand in the way of a shot
:func:`side`          ``w * max(0, -s p_y)`` for a side ``s`` in {-1, 0, +1}: a supporter stays
                      on its side of the field (see :func:`supporter_field` for the sides)
:func:`anchor`        ``w * huber(|p - a|)``: the pull of the formation target ``a``
====================  ========================================================================

``huber(e) = e² / (2 h)`` for ``|e| < h`` and ``|e| - h / 2`` beyond (``h`` the term's
"soft" radius): linear far away, but with a gradient that fades to zero at the attractor, so
a player settles there instead of stepping back and forth across it. Where a term has a
kink (a corner of the penalty area, the end of a ramp) the gradient of one side is used;
where a distance is zero its direction is taken as zero (players on the same spot are pushed
apart along y, the lower row towards +y).
"""

from __future__ import annotations

from agents.roles.field_params import FIELD_DTYPE, FieldParams
from agents.roles.field_terms import (
    anchor,
    ball_distance,
    corridor_block,
    corridor_clear,
    defensive_bias,
    descend,
    forward_bias,
    own_area,
    side,
    supporter_field,
    supporter_sides,
    teammates,
    walls,
)

__all__ = [
    "FIELD_DTYPE", "FieldParams", "anchor", "ball_distance", "corridor_block", "corridor_clear", "defensive_bias",
    "descend", "forward_bias", "own_area", "side", "supporter_field", "supporter_sides", "teammates", "walls",
]
