"""The referee's judges: which ones a setup has, the hooks they hear and in what order."""

import pytest

from soccer_sim.analysis import PlayAnalysis
from soccer_sim.config import MatchConfig, TackleConfig
from soccer_sim.referee import Referee
from soccer_sim.setup import MatchSetup
from soccer_sim.rules import HOOKS, Hooks, Judge, PlayModes
from soccer_sim.state import AWAY, HOME, EventKind, EventLog, PlayMode
from tests.soccer_sim.referee_world import N, catch, config_with, kick, kinds, make_world, step

DEFAULT_ORDER = ["ball_out", "offside", "goal_kick", "touch", "plays", "goalkeeper", "stuck_ball", "fouls"]


class Recorder(Judge):
    """Records every hook it hears, with the play mode at the time; never stops play."""

    name = "recorder"

    def __init__(self) -> None:
        self.calls: list[tuple] = []

    def kick_taken(self, state, rows, mode, x, y):
        self.calls.append(("kick_taken", tuple(rows), PlayMode(mode)))
        return False

    def ball_touched(self, state, rows, x, y):
        self.calls.append(("ball_touched", tuple(rows)))
        return False

    def ball_caught(self, state, row, x, y):
        self.calls.append(("ball_caught", row))

    def analyse(self, state, x, y):
        self.calls.append(("analyse", state.cycle))
        return False

    def play_mode_change(self, state, mode):
        self.calls.append(("play_mode_change", PlayMode(mode)))

    def ball_placed(self, state, x, y):
        self.calls.append(("ball_placed", (x, y)))

    def ball_dropped(self, state, x, y):
        self.calls.append(("ball_dropped", (x, y)))

    def goal_scored(self, state, scorer, last_team, last_index):
        self.calls.append(("goal_scored", scorer, last_team, last_index))

    def half_time(self, state):
        self.calls.append(("half_time",))


def names(referee: Referee) -> list[str]:
    return [j.name for j in referee.judges]


def test_default_judges_in_order():
    ref, _, _ = make_world()
    assert names(ref) == DEFAULT_ORDER
    assert isinstance(ref.modes, PlayModes)


@pytest.mark.parametrize("rules, missing", [
    ({"offside": False}, "offside"),
    ({"goal_kick_leaves_area": False}, "goal_kick"),
    ({"stuck_ball_cycles": None}, "stuck_ball"),
])
def test_a_rule_switched_off_has_no_judge(rules, missing):
    ref, _, _ = make_world(config=config_with(**rules))
    assert names(ref) == [name for name in DEFAULT_ORDER if name != missing]


def test_tackles_switched_off_have_no_foul_judge():
    ref, _, _ = make_world(config=MatchConfig(tackles=TackleConfig(enabled=False)))
    assert names(ref) == [name for name in DEFAULT_ORDER if name != "fouls"]


def test_offside_switched_off_lets_a_player_in_an_offside_position_play():
    for offside, expected in ((True, PlayMode.FREE_KICK), (False, PlayMode.PLAY_ON)):
        ref, st, ev = make_world(ball=(10.0, 0.0), last_touch=5, config=config_with(offside=offside),
                                 moves={5: (10.0, 0.0), 6: (40.0, 5.0)})
        kick(ref, st, [5], (2.0, 0.0))
        st.ball[:] = (40.0, 5.0)
        kick(ref, st, [6], (0.5, 0.0))
        assert st.play_mode == expected


def test_a_judge_added_hears_every_hook_in_order():
    ref, st, ev = make_world(ball=(0.0, 0.0), moves={5: (0.0, 0.5), 6: (20.0, 10.0)})
    rec = Recorder()
    ref.add_judge(rec)
    assert ref.judges[-1] is rec
    kick(ref, st, [5], (1.5, 0.0))  # in play on: no play-mode change
    st.ball[:] = (20.0, 10.0)
    step(ref, st, touchers=[6])  # a team-mate's body touch: PASS, then the cycle is analysed
    st.ball[:] = (30.0, 40.0)  # over the touchline
    step(ref, st)
    # The ball out ends the analysis of cycle 101 before the recorder (last) hears it.
    assert rec.calls == [
        ("kick_taken", (5,), PlayMode.PLAY_ON),
        ("ball_touched", (6,)),
        ("analyse", 100),
        ("ball_placed", tuple(st.ball.tolist())),
        ("play_mode_change", PlayMode.KICK_IN),
    ]
    assert kinds(ev) == [EventKind.KICK, EventKind.TOUCH, EventKind.PASS, EventKind.OUT, EventKind.SET_PLAY]


def test_catch_goal_and_half_time_hooks():
    ref, st, ev = make_world(ball=(-47.0, 2.5), ball_vel=(-1.0, 0.2), moves={0: (-48.0, 2.0)}, last_touch=N + 9)
    rec = Recorder()
    ref.add_judge(rec)
    catch(ref, st, HOME)
    assert rec.calls == [("ball_caught", 0), ("play_mode_change", PlayMode.GOALIE_HOLDS)]
    rec.calls.clear()
    kick(ref, st, [0], (2.0, 0.0))  # the held ball released: play on again
    assert rec.calls == [("kick_taken", (0,), PlayMode.GOALIE_HOLDS), ("play_mode_change", PlayMode.PLAY_ON)]
    rec.calls.clear()
    st.ball[:] = (53.0, 0.0)  # in the away goal; last touch: the home goalkeeper
    step(ref, st)
    assert rec.calls == [("goal_scored", HOME, HOME, 0), ("ball_placed", (0.0, 0.0)),
                         ("play_mode_change", PlayMode.AFTER_GOAL)]
    rec.calls.clear()
    st.cycle = ref.config.rules.half_cycles - 1
    step(ref, st)
    # The pause ends (kick-off), then half time: the ends change and away kicks off.
    assert rec.calls == [("ball_placed", (0.0, 0.0)), ("play_mode_change", PlayMode.KICK_OFF),
                         ("half_time",), ("ball_placed", (0.0, 0.0)), ("play_mode_change", PlayMode.KICK_OFF)]
    assert (st.half, st.mode_team) == (1, AWAY)


def test_a_judge_stopping_play_hides_the_kick_from_the_judges_after_it():
    class Whistle(Judge):
        name = "whistle"

        def kick_taken(self, state, rows, mode, x, y):
            return True

    ref, st, ev = make_world(ball=(10.0, 0.0), mode=PlayMode.FREE_KICK, mode_team=HOME, moves={5: (10.0, 0.5)})
    rec = Recorder()
    ref.hooks.set([Whistle(), *ref.judges, rec])
    kick(ref, st, [5], (3.0, 0.0))  # would be a shot, and would take the free kick
    assert rec.calls == []
    assert kinds(ev) == [EventKind.KICK]  # no SHOT, no SET_PLAY
    assert st.play_mode == PlayMode.FREE_KICK


def test_stuck_ball_drop_is_heard_as_ball_dropped():
    ref, st, ev = make_world(ball=(0.0, 0.0), config=config_with(stuck_ball_cycles=3))
    rec = Recorder()
    ref.add_judge(rec)
    for _ in range(4):
        step(ref, st)
    assert ("ball_dropped", (0.0, 0.0)) in rec.calls
    assert [c[0] for c in rec.calls if c[0] != "analyse"] == ["ball_dropped"]
    assert EventKind.DROP_BALL in kinds(ev)


def test_hooks_call_only_the_judges_that_override_them():
    class OnlyAnalyse(Judge):
        def analyse(self, state, x, y):
            return False

    only, rec = OnlyAnalyse(), Recorder()
    hooks = Hooks([only, rec])
    assert [c.__self__ for c in hooks.analyse_judges] == [only, rec]
    assert [c.__self__ for c in hooks.kick_judges] == [rec]
    assert len(HOOKS) == 10 and all(hasattr(Judge, h) for h in HOOKS)


def test_play_analysis_is_the_one_pass_and_shot_definition():
    ref, st, ev = make_world(ball=(40.0, 0.0), moves={9: (40.0, 0.5)})
    assert sum(isinstance(j, PlayAnalysis) for j in ref.judges) == 1
    kick(ref, st, [9], (2.5, 0.0))  # towards the away goal at +x, well within reach
    assert ev.of_kind(EventKind.SHOT)[0][1:3] == (HOME, 9)
    assert ref.plays.passer() == 9  # the goalkeeper's back-pass rule asks the same object
    assert Referee(MatchSetup.resolve(config_with()), EventLog()).plays.passer() == -1
