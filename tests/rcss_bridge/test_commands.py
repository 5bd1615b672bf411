"""The command translation (rcss_bridge.commands, rcss_bridge.body_control) against figures
recorded from rcssserver 19 (tests/data/rcssserver/: kick.json, dash.json, goalkeeper.json,
tackle.json) and the server's parameters recorded with the bridge's transcripts."""

from __future__ import annotations

import json
import math
import re
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from rcss_bridge.body_control import ServerRules, choose_run, dash_rate, neck_moment
from rcss_bridge.commands import CommandTranslator, PlayerBodies, number, player_type_commands
from rcss_bridge.errors import CommandError, ProtocolError
from rcss_bridge.messages import read_message
from rcss_bridge.params import ServerParameters
from rcss_bridge.views_builder import ViewsBuilder
from soccer_sim.body import turn_angle
from soccer_sim.kick_rate import kick_distance_rate, kick_effectiveness
from soccer_sim.team import TeamCommand
from tests.rcss_bridge.recorded import received, truth

DATA = Path(__file__).resolve().parents[1] / "data" / "rcssserver"
N = 11
GOALIE = 0


def trace(name: str) -> dict:
    return json.loads((DATA / f"{name}.json").read_text())


@pytest.fixture()
def translator(parameters) -> CommandTranslator:
    return CommandTranslator("BRIDGE", N, ServerRules.from_server(parameters.server), parameters.types,
                             parameters.match_config(), GOALIE)


def bodies(body=0.0, velocity=(0.0, 0.0), ball=(np.nan, np.nan), neck=0.0, **changes) -> PlayerBodies:
    """Every player alike: body direction, velocity, ball offset and neck as given (team frame)."""
    values = dict(body_direction=np.full(N, float(body)), neck=np.full(N, float(neck)),
                  velocity=np.tile(np.asarray(velocity, float), (N, 1)), ball_offset=np.tile(np.asarray(ball, float), (N, 1)),
                  effort=np.ones(N), types=np.zeros(N, dtype=np.int64), present=np.ones(N, dtype=bool),
                  frozen=np.zeros(N, dtype=np.int64), holds_ball=np.zeros(N, dtype=bool))
    values.update(changes)
    return PlayerBodies(**values)


def command(**rows) -> TeamCommand:
    """A command with nothing asked but the given rows: ``dash={row: (x, y)}``, ``kick=...``,
    ``move=...``, ``tackle={row: degrees}``, ``foul={row: True}``, and the other fields as given."""
    dash, kick = np.zeros((N, 2)), np.zeros((N, 2))
    for row, vector in rows.pop("dash", {}).items():
        dash[row] = vector
    for row, vector in rows.pop("kick", {}).items():
        kick[row] = vector
    fields = {}
    if "move" in rows:
        fields["move"] = np.zeros((N, 2))
        for row, vector in rows.pop("move").items():
            fields["move"][row] = vector
    if "tackle" in rows:
        fields["tackle"] = np.full(N, np.nan)
        for row, degrees in rows.pop("tackle").items():
            fields["tackle"][row] = degrees
    if "foul" in rows:
        fields["foul"] = np.zeros(N, dtype=bool)
        for row in rows.pop("foul"):
            fields["foul"][row] = True
    fields.update(rows)
    return TeamCommand(dash=dash, kick=kick, **fields)


def body_of(order) -> list[tuple[str, list[float]]]:
    """The commands of an order as (name, numbers)."""
    return [(m.group(1), [float(v) for v in m.group(2).split() if v not in ("on", "off")])
            for m in re.finditer(r"\((\w+)((?: [^()]+)?)\)", order.commands)]


def only_body(order) -> tuple[str, list[float]]:
    """The order's one body command (turn_neck left out)."""
    found = [c for c in body_of(order) if c[0] != "turn_neck"]
    assert len(found) == 1, order
    return found[0]


def angle_gap(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


# --------------------------------------------------------------------------------- kicks
KICKS = [name for name in trace("kick")["kicks"] if not name.startswith("two_kicks")]


@pytest.mark.parametrize("name", KICKS)
def test_a_kick_asking_for_the_recorded_ball_speed_is_the_recorded_kick(translator, parameters, name):
    """The server kicked (kick 100 DIR) a ball at rest at ``ball_rel`` from a still player facing
    +x and the ball left at ``first_cycle``. A team asking the simulator for that velocity (its
    request: the velocity over the simulator's rate, the still player facing the ball) gets
    (kick 100 DIR) back: the kick rate of the ball's place relative to the real body."""
    kick = trace("kick")["kicks"][name]
    offset, result = np.array(kick["ball_rel"]), np.array(kick["first_cycle"])
    phys = parameters.match_config().physics
    simulator_rate = kick_effectiveness(kick_distance_rate(float(np.hypot(*offset)), phys.player_radius + phys.ball_radius,
                                                           phys.kickable_margin), 0.0, 0.25, 0.25)
    orders = translator.translate(command(kick={3: result / simulator_rate}), bodies(ball=offset), "play_on")
    name_, (power, direction) = only_body(orders[3])
    recorded_direction = float(name.split("_dir")[1]) if "_dir" in name else 0.0
    assert name_ == "kick" and power == pytest.approx(100.0, abs=0.02)
    assert angle_gap(direction, recorded_direction) < 0.01


def test_a_kick_makes_up_for_a_body_the_simulator_would_have_turned(translator, parameters):
    """A sprinter whose ball lies beside it: the simulator's body model turns it towards the
    ball; the real body still faces the run, so the server's rate is lower and the power higher,
    to give the ball the same change; beyond maxpower the kick is capped."""
    phys = parameters.match_config().physics
    offset = np.array([0.0, 0.6])  # 90 degrees left of the body (0), within reach
    state = bodies(body=0.0, velocity=(0.2, 0.0), ball=offset)
    request = np.array([1.0, 0.0])
    orders = translator.translate(command(kick={4: request}), state, "play_on")
    _, (power, direction) = only_body(orders[4])
    simulator = translator.simulator_kick_rate(4, tuple(offset), state)
    server = kick_effectiveness(kick_distance_rate(0.6, 0.385, 0.7), 0.5, phys.kick_distance_penalty,
                                phys.kick_angle_penalty)
    assert simulator > server  # at 0.2 m/cycle the modelled body faces the ball
    assert power * 0.027 * server == pytest.approx(1.0 * simulator, abs=0.01)
    assert direction == 0.0
    orders = translator.translate(command(kick={4: (2.7, 0.0)}), state, "play_on")
    assert only_body(orders[4])[1][0] == 100.0
    # a ball out of reach (the server will not kick it) or unknown: the request at face value
    for far in ((30.0, 4.0), (np.nan, np.nan)):
        orders = translator.translate(command(kick={4: (1.35, 0.0)}), bodies(ball=far), "play_on")
        assert only_body(orders[4]) == ("kick", [50.0, 0.0])


def test_a_held_ball_is_kicked_at_full_rate(translator):
    """goalkeeper.json: the keeper holding the ball sent (kick 50 0) and the ball left at 1.35
    m/cycle (50 x 0.027): the held ball lies in front of the body."""
    hold = trace("goalkeeper")["hold"]
    t10, t11 = hold[9], hold[10]
    assert t10["order"] == "(kick 50 0)"
    speed = math.hypot(t11["ball"][0] - t10["ball"][0], t11["ball"][1] - t10["ball"][1])
    body = math.degrees(math.atan2(t10["ball"][1] - t10["keeper"][1], t10["ball"][0] - t10["keeper"][0]))
    offset = np.array(t10["ball"]) - np.array(t10["keeper"])
    state = bodies(body=body, ball=offset, holds_ball=np.arange(N) == GOALIE)
    a = math.radians(body)
    orders = translator.translate(command(kick={GOALIE: (speed * math.cos(a), speed * math.sin(a))}), state,
                                  "free_kick_l")
    assert only_body(orders[GOALIE]) == ("kick", [pytest.approx(50.0, abs=0.05), 0.0])


# --------------------------------------------------------------------------------- dashes
@pytest.mark.parametrize("direction", ["0", "45", "90", "-90", "180"])
def test_a_dash_asking_for_the_recorded_acceleration_is_the_recorded_dash(translator, direction):
    """dash.json: (dash 100 DIR) from rest, body 0; the first cycle's displacement is the
    acceleration. Asking for it gives (dash 100 DIR) (180 as -180), and half of it power 50."""
    record = trace("dash")
    accel = np.array([record["forward"]["speed"][0], 0.0]) if direction == "0" else np.array(record["dash_dir"][direction][0])
    for share, power in ((1.0, 100.0), (0.5, 50.0)):
        orders = translator.translate(command(dash={2: accel * share}), bodies(body=0.0), "play_on")
        name, (got_power, got_direction) = only_body(orders[2])
        assert name == "dash" and got_power == pytest.approx(power, abs=0.2)
        assert angle_gap(got_direction, float(direction)) < 0.01


def test_the_dash_rate_is_the_servers_by_direction_from_the_body(translator):
    record = trace("dash")["dash_dir"]
    for direction in ("45", "90", "-90", "180"):
        first = math.hypot(*record[direction][0])
        assert dash_rate(float(direction), translator.rules) * 100 * 0.006 == pytest.approx(first, abs=1e-4)


def test_a_strong_request_well_off_the_body_turns_first_a_gentle_or_nearly_straight_one_dashes(translator):
    full = 0.6
    for degrees, turns in ((30.0, False), (60.0, True), (90.0, True), (-135.0, True)):
        a = math.radians(degrees)
        orders = translator.translate(command(dash={5: (full * math.cos(a), full * math.sin(a))}), bodies(), "play_on")
        name, values = only_body(orders[5])
        assert name == ("turn" if turns else "dash"), degrees
        if turns:
            assert values[0] == pytest.approx(degrees, abs=0.01)  # at rest the whole turn at once
    # a side request the body's angle lets through in full is a dash (0.24 = 0.4 x 0.6)
    orders = translator.translate(command(dash={5: (0.0, 0.2)}), bodies(), "play_on")
    assert only_body(orders[5])[0] == "dash"


def test_the_turn_is_the_servers_by_speed_and_inertia(translator):
    """goalkeeper.json: the keeper moving at 0.936 x 0.4 m/cycle along its body sent (turn 90);
    its body (where the held ball then lay) turned by 90 / (1 + 5 x 0.3744) = 31.3 degrees. A
    player at that speed with nothing to do and the ball there turns to it with (turn 90)."""
    hold = trace("goalkeeper")["hold"]
    t8, t9, t10 = hold[7], hold[8], hold[9]
    assert t9["order"] == "(turn 90)"
    speed = (t9["keeper"][0] - t8["keeper"][0]) * 0.4
    turned = math.degrees(math.atan2(t10["ball"][1] - t10["keeper"][1], t10["ball"][0] - t10["keeper"][0]))
    assert turn_angle(90.0, speed, 5.0) == pytest.approx(turned, abs=0.05)
    a = math.radians(turned)
    state = bodies(body=0.0, velocity=(speed, 0.0), ball=(0.9 * math.cos(a), 0.9 * math.sin(a)))
    orders = translator.translate(command(), state, "play_on")
    assert only_body(orders[6]) == ("turn", [pytest.approx(90.0, abs=0.2)])
    # a request straight behind a player at that speed: the largest turn is too short, the
    # back dash wins (the velocity decays meanwhile); at rest the turn wins
    run = choose_run(-0.6, 0.0, 0.0, speed, 0.0, 1.0, translator.types[0], translator.rules)
    assert not run.turn and run.direction in (180.0, -180.0)
    assert choose_run(-0.6, 0.0, 0.0, 0.0, 0.0, 1.0, translator.types[0], translator.rules).turn


# --------------------------------------------------------------------------------- one body command
def test_one_body_command_by_the_simulators_priority(translator):
    ahead = bodies(ball=(0.6, 0.0))
    orders = translator.translate(command(dash={1: (0.3, 0), 2: (0.3, 0), GOALIE: (0.3, 0)},
                                          kick={1: (1.0, 0), 2: (1.0, 0), GOALIE: (1.0, 0)},
                                          tackle={2: 0.0}, catch=True), ahead, "play_on")
    assert only_body(orders[1])[0] == "kick"          # kick > dash
    assert only_body(orders[2])[0] == "tackle"        # tackle > kick > dash
    assert only_body(orders[GOALIE])[0] == "catch"    # catch > kick > dash
    assert translator.sent["dropped"] == 1 + 2 + 2
    orders = translator.translate(command(dash={3: (0.3, 0)}, move={3: (-10, 5)}), ahead, "before_kick_off")
    assert only_body(orders[3]) == ("move", [-10.0, 5.0])  # move > dash
    orders = translator.translate(command(dash={3: (0.3, 0)}, move={3: (-10, 5)}, kick={3: (1, 0)}), ahead,
                                  "before_kick_off")
    assert only_body(orders[3])[0] == "kick"             # kick > move


def test_the_catch_goes_to_the_goalkeeper_towards_the_ball_within_the_catch_angles(translator):
    orders = translator.translate(command(catch=True), bodies(body=0.0, ball=(1.0, 0.0)), "play_on")
    assert only_body(orders[GOALIE]) == ("catch", [0.0])   # goalkeeper.json's first order: (catch 0)
    assert all("catch" not in orders[row].commands for row in range(1, N))
    orders = translator.translate(command(catch=True), bodies(body=10.0, ball=(0.0, 1.0)), "play_on")
    assert only_body(orders[GOALIE]) == ("catch", [80.0])
    orders = translator.translate(command(catch=True), bodies(body=0.0, ball=(-1.0, -0.2)), "play_on")
    assert only_body(orders[GOALIE]) == ("catch", [-90.0])  # min_catch_angle


def test_the_tackle_direction_is_relative_to_the_body_and_a_foul_is_on(translator):
    """tackle.json's (tackle DIR off) from body 0: a tackle towards DIR in the team frame."""
    for record in trace("tackle")["tackle_speed"].values():
        orders = translator.translate(command(tackle={7: record["dir"]}), bodies(body=0.0), "play_on")
        name, (direction,) = only_body(orders[7])
        assert name == "tackle" and angle_gap(direction, record["dir"]) < 0.01 and "off" in orders[7].commands
    orders = translator.translate(command(tackle={7: 45.0}, foul=[7]), bodies(body=30.0), "play_on")
    assert only_body(orders[7]) == ("tackle", [15.0]) and "(tackle 15 on)" in orders[7].commands


def test_moves_only_where_the_server_allows_them(translator):
    state = bodies()
    for mode in ("play_on", "kick_off_l", "free_kick_r", "goal_kick_l", "drop_ball"):
        orders = translator.translate(command(move={4: (-20, 3)}, dash={4: (0.1, 0)}), state, mode)
        assert only_body(orders[4])[0] == "dash", mode
    for mode in ("before_kick_off", "goal_l", "goal_r"):
        orders = translator.translate(command(move={4: (-20, 3)}), state, mode)
        assert only_body(orders[4]) == ("move", [-20.0, 3.0]), mode


def test_the_goalkeeper_moves_after_a_catch_as_often_as_the_server_took_them(translator):
    """goalkeeper.json: after the catch the keeper's third move was refused (too_many_moves):
    the translation sends the first goalie_max_moves and no more, until the next catch."""
    hold = trace("goalkeeper")["hold"]
    moves = [s for s in hold if s.get("order", "").startswith("(move")]
    refused = sum(1 for s in hold if "(error too_many_moves)" in s["errors"])
    accepted = len(moves) - refused
    assert accepted == translator.rules.goalie_max_moves == 2
    holding = bodies(holds_ball=np.arange(N) == GOALIE)
    sent = []
    for state in moves:
        x, y = (float(v) for v in state["order"][6:-1].split())
        orders = translator.translate(command(move={GOALIE: (x, y), 5: (x, y)}), holding, "free_kick_l")
        sent.append("move" in orders[GOALIE].commands)
        assert "move" not in orders[5].commands  # only the keeper, only while it holds
    assert sent == [True] * accepted + [False] * refused
    translator.translate(command(), bodies(), "play_on")  # the hold ends; a new catch, new moves
    orders = translator.translate(command(move={GOALIE: (-45, 0)}), holding, "free_kick_l")
    assert only_body(orders[GOALIE])[0] == "move"


def test_players_absent_frozen_or_without_a_body_direction(translator):
    present = np.arange(N) != 8
    frozen = np.where(np.arange(N) == 9, 3, 0)
    body = np.where(np.arange(N) == 10, np.nan, 0.0)
    state = bodies(ball=(5.0, 0.0), present=present, frozen=frozen, body_direction=body)
    orders = translator.translate(command(dash={8: (0.5, 0), 9: (0.5, 0), 10: (0.5, 0)}), state, "play_on")
    assert 8 not in orders                                          # sent off: no order
    assert [c for c in body_of(orders[9]) if c[0] != "turn_neck"] == []  # frozen: no body command
    assert orders[10].commands == "" and translator.sent["unaimed"] == 1
    orders = translator.translate(command(move={10: (-3, 0)}), state, "before_kick_off")
    assert only_body(orders[10]) == ("move", [-3.0, 0.0])          # a move needs no body


def test_an_idle_player_turns_to_the_modelled_body_and_says(translator):
    orders = translator.translate(command(say=["HI"] + [None] * (N - 1)), bodies(body=0.0, ball=(0.0, -3.0)),
                                  "play_on")
    assert only_body(orders[0]) == ("turn", [-90.0]) and orders[0].say == "HI" and orders[1].say is None


# --------------------------------------------------------------------------------- the neck
def test_the_neck_keeps_the_ball_in_view_within_the_servers_limits(translator):
    rules = translator.rules
    assert neck_moment(0.0, 0.0, 40.0, rules) == 40.0
    assert neck_moment(0.0, 0.0, 170.0, rules) == rules.max_neck_angle         # maxneckang
    assert neck_moment(-90.0, 0.0, 90.0, rules) == 180.0                        # a whole maxneckmoment
    assert neck_moment(-90.0, 0.0, 90.0, replace(rules, max_neck_moment=60.0)) == 60.0
    assert neck_moment(30.0, 0.0, math.nan, rules) == rules.min_neck_angle - 30.0  # unknown ball: swing
    assert neck_moment(-30.0, 0.0, math.nan, rules) == rules.max_neck_angle + 30.0
    # after this step's turn: a still player turning 90 to a ball at 90 keeps its neck at 0
    orders = translator.translate(command(dash={2: (0.0, 0.6)}), bodies(body=0.0, ball=(0.0, 5.0)), "play_on")
    assert only_body(orders[2]) == ("turn", [90.0]) and "turn_neck" not in orders[2].commands
    orders = translator.translate(command(dash={2: (0.6, 0.0)}), bodies(body=0.0, ball=(0.0, 5.0), neck=-20.0),
                                  "play_on")
    assert ("turn_neck", [110.0]) in body_of(orders[2])


def test_a_commands_own_neck_turn_is_sent_as_it_is_within_the_servers_moments(translator):
    """A team that turns the neck (TeamCommand.turn_neck) has that turn sent, not the ball
    tracker's; NaN and 0 send none, as the simulator turns none; with any body command and
    also for a frozen player (rcssserver takes turn_neck then too)."""
    turns = np.full(N, np.nan)
    turns[[1, 2, 3, 4, 5]] = [35.5, -500.0, 0.0, 250.0, -20.0]
    frozen = np.zeros(N, dtype=np.int64)
    frozen[5] = 3
    orders = translator.translate(command(dash={2: (0.6, 0.0)}, kick={4: (1.0, 0.0)}, turn_neck=turns),
                                  bodies(body=0.0, ball=(0.0, 5.0), neck=40.0, frozen=frozen), "play_on")
    necks = {row: [c for c in body_of(orders[row]) if c[0] == "turn_neck"] for row in range(N)}
    assert necks[1] == [("turn_neck", [35.5])]
    assert necks[2] == [("turn_neck", [translator.rules.min_neck_moment])]  # -500 clipped to minneckmoment
    assert only_body(orders[2])[0] == "dash"
    assert necks[3] == [] and necks[0] == [] and necks[6] == []  # 0 and NaN: no turn, and no ball tracking
    assert necks[4] == [("turn_neck", [180.0])] and only_body(orders[4])[0] == "kick"
    assert orders[5].commands == "(turn_neck -20)"  # frozen: the neck only
    # without a turn_neck the translation keeps the ball in view as before
    orders = translator.translate(command(), bodies(body=0.0, ball=(0.0, 5.0), neck=40.0), "play_on")
    assert body_of(orders[1]) == [("turn", [90.0]), ("turn_neck", [-40.0])]  # the body turns to the ball, the face too


def test_a_commands_view_width_is_sent_when_it_differs_from_the_players(translator):
    """``change_view`` codes (NARROW 0, NORMAL 1, WIDE 2, KEEP -1) become ``(change_view
    WIDTH)`` only for a player whose sense_body told another width (nothing for KEEP), with
    any body command and the neck."""
    widths = np.full(N, -1)
    widths[[1, 2, 3, 4]] = [0, 2, 1, 0]
    told = np.ones(N, dtype=np.int64)
    told[4] = 0  # already narrow
    turns = np.zeros(N)
    turns[1] = 30.0
    orders = translator.translate(command(dash={2: (0.6, 0.0)}, change_view=widths, turn_neck=turns),
                                  bodies(ball=(0.0, 5.0), view_width=told), "play_on")
    assert "(change_view narrow)" in orders[1].commands and "(turn_neck 30)" in orders[1].commands
    assert "(change_view wide)" in orders[2].commands and orders[2].commands.startswith("(dash ")
    assert all("change_view" not in orders[row].commands for row in (0, 3, 4, 5))
    with pytest.raises(CommandError, match=r"command.change_view\[0\] is 5: not a view width"):
        translator.translate(command(change_view=np.full(N, 5)), bodies(), "play_on")


@pytest.mark.parametrize("turns, message", [
    (np.full(N, np.inf), "command.turn_neck is infinite: inf"),
    (np.zeros(N + 1), r"command.turn_neck must have shape \(11,\)"),
    (np.array(["up"] * N), "command.turn_neck must be numeric"),
])
def test_a_bad_neck_turn_is_a_command_error(translator, turns, message):
    with pytest.raises(CommandError, match=message):
        translator.translate(command(turn_neck=turns), bodies(ball=(0.0, 5.0)), "play_on")


def test_the_neck_follows_a_belief_only_while_the_ball_was_seen_lately(translator):
    """A ball believed at 60 degrees: followed for BALL_LOOK_STEPS steps after the player last
    saw it, then the neck looks around (to the other end of its range) until it sees it."""
    from rcss_bridge.commands import BALL_LOOK_STEPS

    rules = translator.rules
    for unseen, expected in ((0, 60.0), (BALL_LOOK_STEPS, 60.0), (BALL_LOOK_STEPS + 1, rules.max_neck_angle)):
        state = bodies(body=0.0, ball=(0.5, 0.5 * math.sqrt(3.0)))
        state.ball_unseen = np.full(N, unseen)
        orders = translator.translate(command(dash={5: (0.6, 0.0)}), state, "play_on")  # a dash ahead: no turn
        turn = dict(body_of(orders[5])).get("turn_neck", [0.0])[0]
        assert turn == pytest.approx(expected, abs=0.01), unseen


# --------------------------------------------------------------------------------- frames
def test_the_right_sides_commands_are_relative_to_its_real_body():
    """Views of the right-hand player built from its recorded messages (team frame: turned by
    180 degrees) and a request towards the ball: the dash's direction relative to the body
    is the one the trainer's exact positions give."""
    builder = ViewsBuilder("OTHERS", "r", N, [0.4] * 18)
    box = received("OTHERS-1")
    texts = received("BRIDGE-1")[-1]
    params = ServerParameters.from_messages(
        next(t for t in texts if t.startswith("(server_param")), next(t for t in texts if t.startswith("(player_param")),
        [t for t in texts if t.startswith("(player_type")])
    translator = CommandTranslator("OTHERS", N, ServerRules.from_server(params.server), params.types,
                                   params.match_config(), GOALIE)
    checked = 0
    for counter, step in enumerate(sorted(s for s in box if s >= 0)):
        views = builder.update(counter, {0: [read_message(t) for t in box[step]]})
        exact = truth().get(step)
        if not (views.localised[0] and views.ball_seen[0]) or exact is None:
            continue
        x, y, body = exact[("OTHERS", 1)]
        bx, by = exact["ball"]
        if math.hypot(bx - x, by - y) < 3.0:
            continue
        state = PlayerBodies.from_views(views, builder.necks)
        offset = state.ball_offset[0] / np.linalg.norm(state.ball_offset[0]) * 0.05  # gentle: always a dash
        orders = translator.translate(TeamCommand(dash=np.vstack([offset, np.zeros((N - 1, 2))]), kick=np.zeros((N, 2))),
                                      state, builder.referee.server_mode)
        name, (_, direction) = only_body(orders[0])
        expected = math.degrees(math.atan2(by - y, bx - x)) - body
        assert name == "dash" and angle_gap(direction, expected) < 3.0
        checked += 1
    assert checked >= 3


# --------------------------------------------------------------------------------- bad input, the coach
def test_bad_commands_are_the_bridges_error_naming_the_player(translator):
    state = bodies()
    with pytest.raises(CommandError, match=r"command.dash must have shape \(11, 2\)"):
        translator.translate(TeamCommand(dash=np.zeros((10, 2)), kick=np.zeros((N, 2))), state, "play_on")
    kick = np.zeros((N, 2))
    kick[4] = (np.nan, 0.0)
    with pytest.raises(CommandError, match=r"player 4 \(shirt 5\): command.kick is not finite"):
        translator.translate(TeamCommand(dash=np.zeros((N, 2)), kick=kick), state, "play_on")
    with pytest.raises(CommandError, match="command.catch must be a bool"):
        translator.translate(command(catch=2), state, "play_on")
    with pytest.raises(CommandError, match="command.say must be a sequence of 11"):
        translator.translate(command(say=["A"]), state, "play_on")
    with pytest.raises(CommandError, match="command.tackle is infinite"):
        translator.translate(command(tackle={3: math.inf}), state, "play_on")
    with pytest.raises(CommandError, match="expected a TeamCommand"):
        translator.translate("(dash 100)", state, "play_on")
    with pytest.raises(CommandError, match="player type 40 is not one of the server's 18 types"):
        translator.translate(command(), bodies(types=np.full(N, 40)), "play_on")
    with pytest.raises(CommandError, match=r"bodies.velocity must have shape \(11, 2\)"):
        translator.translate(command(), bodies(velocity=(0.0, 0.0, 0.0)), "play_on")
    with pytest.raises(ProtocolError, match="server_param has no numeric maxneckang"):
        ServerRules.from_server({name: 1.0 for name in ("maxpower", "minmoment", "maxmoment", "minneckang")})


def test_the_coach_gives_every_player_its_chosen_type(parameters):
    choice = [0, 1, 1, 2, 3, 4, 5, 6, 7, 8, 0]
    texts = player_type_commands(choice, parameters.types, N, 3, "BRIDGE")
    assert texts[0] == "(change_player_type 1 0)" and texts[2] == "(change_player_type 3 1)" and len(texts) == N
    with pytest.raises(CommandError, match="more than pt_max=1"):
        player_type_commands(choice, parameters.types, N, 1, "BRIDGE")
    with pytest.raises(CommandError, match="must return 11 type ids"):
        player_type_commands(choice[:5], parameters.types, N, 3, "BRIDGE")
    with pytest.raises(CommandError, match=r"player 1 \(shirt 2\).*not a type id"):
        player_type_commands([0, 99] + [0] * 9, parameters.types, N, 3, "BRIDGE")


def test_numbers_are_written_plainly():
    assert [number(v) for v in (100.0, -0.001, 1e-9, 12.346, -179.999, 0.5)] == ["100", "0", "0", "12.35", "-180",
                                                                                 "0.5"]
