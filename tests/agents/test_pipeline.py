"""The built-in team's one pipeline (:mod:`agents.teams.pipeline`): under partial observation
each player decides from its own view alone; under full observation every player believes the
truth, and what is derived from it is computed once for the team."""

from __future__ import annotations

import copy

import numpy as np
import pytest

from soccer_sim import MatchConfig, resolve_team, run_match
from soccer_sim.match import Match
from soccer_sim.perception.config import ObservationConfig
from soccer_sim.state import PlayMode
from soccer_sim.trivial_teams import ChaserTeam

PARTIAL = MatchConfig(observation=ObservationConfig("partial"), max_cycles=120)


class _Recorder(ChaserTeam):
    """A chaser keeping copies of the views its side's players got."""

    def act(self, views):
        self.seen = getattr(self, "seen", [])
        self.seen.append(copy.deepcopy(views))
        return super().act(views)


def _recorded_views():
    recorder = _Recorder()
    match = Match(recorder, ChaserTeam(), seed=4, config=PARTIAL)
    match.run()
    return recorder.seen, match


def test_changing_one_players_view_changes_no_other_players_command():
    views, match = _recorded_views()
    info = match.setup.side_info(0, match.team_names)
    teams = []
    for _ in range(2):
        team, _ = resolve_team("mmdr")
        team.reset(info, PARTIAL, np.random.default_rng(7))
        teams.append(team)
    for v in views[:80]:
        commands = [team.act(copy.deepcopy(v)) for team in teams]
        np.testing.assert_array_equal(commands[0].dash, commands[1].dash)
    last = views[80]
    altered = copy.deepcopy(last)
    j = 5
    altered.ball[j] = (30.0, -20.0)
    altered.ball_seen[j] = True
    altered.ball_distance[j] = 25.0
    altered.position[j] += 3.0
    altered.heard_mates = tuple(((0, "xxxxxxxxxx"),) if i == j else m for i, m in enumerate(last.heard_mates))
    first = copy.deepcopy(teams[0].act(copy.deepcopy(last)))
    second = teams[1].act(altered)
    others = np.arange(11) != j
    np.testing.assert_array_equal(first.dash[others], second.dash[others])
    np.testing.assert_array_equal(first.kick[others], second.kick[others])
    assert [first.say[i] for i in range(11) if i != j] == [second.say[i] for i in range(11) if i != j]
    assert not np.array_equal(first.dash[j], second.dash[j]) or first.say[j] != second.say[j]


def test_a_decentralised_match_plays_reports_conflicts_and_is_deterministic():
    config = MatchConfig(observation=ObservationConfig("partial"), max_cycles=400)
    one = run_match("mmdr", "static", seed=2, config=config)
    two = run_match("mmdr", "static", seed=2, config=config)
    np.testing.assert_array_equal(one.state.pos, two.state.pos)
    home = one.statistics[0]
    assert home.kicks > 0 and home.distance_run > 1000.0
    reported = home.reported
    assert 0.0 <= reported["role_conflict_share"] <= 1.0 and "believed_unfilled_share" in reported
    # a role two players believe they hold means they follow different assignments
    assert 0.0 < reported["all_follow_one_share"] < 1.0
    assert reported["all_follow_one_share"] + reported["role_conflict_share"] <= 1.0 + 1e-9
    assert reported["agreement_latency_median"] >= 1.0


_SCRIPT = """
from soccer_sim import MatchConfig, run_match
from soccer_sim.perception.config import ObservationConfig
config = MatchConfig(observation=ObservationConfig("partial"), max_cycles=150)
result = run_match("mmd+msd2", "counter-442", seed=6, config=config)
print(result.state.pos.tobytes().hex())
"""


@pytest.mark.slow  # the default suite checks a partial match across processes with chasers
def test_a_decentralised_match_is_the_same_in_another_process():
    import subprocess
    import sys

    config = MatchConfig(observation=ObservationConfig("partial"), max_cycles=150)
    here = run_match("mmd+msd2", "counter-442", seed=6, config=config)
    out = subprocess.run([sys.executable, "-c", _SCRIPT], capture_output=True, text=True, check=True).stdout.split()
    assert out[-1] == here.state.pos.tobytes().hex()


def test_before_a_kick_off_every_player_lines_up_in_its_own_role():
    # No word is needed for a kick-off: each player takes its shirt-number role, so no two
    # players are placed on one spot (they would be, each sure the role is its own).
    match = Match("mmdr", "mmd+msd2", seed=3, config=PARTIAL)
    match.start()
    for _ in range(3):
        match.step()
        for team in match.teams:
            pipeline = team.pipeline
            outfield = pipeline.outfield
            roles = pipeline.followed[pipeline.world.belief_of[outfield], pipeline.rank[outfield]]
            np.testing.assert_array_equal(roles, np.arange(len(outfield)))
    for side in (slice(0, 11), slice(11, 22)):
        spots = match.state.pos[side]
        gaps = np.hypot(*(spots[:, None, :] - spots[None, :, :]).transpose(2, 0, 1))
        assert gaps[~np.eye(11, dtype=bool)].min() > 2.0


@pytest.mark.parametrize("observation", ["full", "partial"])
def test_only_beliefs_with_a_player_near_the_ball_decide_on_it_in_play_on(observation):
    from agents.teams.decisions import BeliefDecisions
    from agents.teams.pipeline import ON_BALL_DISTANCE

    config = MatchConfig(observation=ObservationConfig(observation), max_cycles=400)
    match = Match("mmdr", "counter-442", seed=1, config=config)
    match.start()
    pipeline = match.teams[0].pipeline
    decided = []
    original = BeliefDecisions.decide

    def spy(decisions, view, race, ball_player, rows, *rest):
        if decisions in pipeline.decisions and view.play_mode == PlayMode.PLAY_ON:
            gaps = np.hypot(*(view.own_pos[rows] - view.ball).T)
            decided.append(float(gaps.min()))
        return original(decisions, view, race, ball_player, rows, *rest)

    BeliefDecisions.decide = spy
    try:
        for _ in range(399):
            match.step()
    finally:
        BeliefDecisions.decide = original
    assert decided, "somebody of ours must have played the ball"
    near_goal = sum(gap >= ON_BALL_DISTANCE for gap in decided)  # (the goalkeeper with the ball near our area)
    assert near_goal < len(decided) / 2


def test_under_full_observation_the_team_assigns_roles_once_a_cycle():
    calls = []
    match = Match("mmdr", "static", seed=2, config=MatchConfig(max_cycles=200))
    match.start()
    pipeline = match.teams[0].pipeline
    assert pipeline.world.belief_of.tolist() == [0] * 11 and len(pipeline.assigners) == 1
    assigner = pipeline.assigners[0]
    original = assigner.assign

    def counted(players, targets, order, previous, context):
        calls.append(context.cycle)
        return original(players, targets, order, previous, context)

    assigner.assign = counted
    for _ in range(199):
        match.step()
    assert calls and len(calls) == len(set(calls))  # at most once a cycle


@pytest.mark.parametrize("scenario", ["3-vs-1-with-keeper", "empty-goal"])
def test_smaller_sides_play_decentralised_each_player_picking_the_roles_it_believes_nearest(scenario):
    config = MatchConfig(observation=ObservationConfig("partial"), max_cycles=200)
    result = run_match("mmdr", "bidding", seed=1, config=config, scenario=scenario)
    assert result.cycles > 0 and result.end_reason in ("goal", "lost", "out", "time_over")


def test_the_speaker_of_each_cycle_alone_says_what_its_beliefs_make(monkeypatch):
    """Under partial observation one player speaks a cycle, in shirt order, and what it says is
    the team message :meth:`TeamBeliefs.message` makes of its beliefs and its proposal."""
    from agents.messages import decode
    from agents.teams.pipeline import Pipeline

    spoken = []
    original = Pipeline.act

    def act(pipeline, views):
        command = original(pipeline, views)
        speakers = [i for i, text in enumerate(command.say) if text is not None]
        assert speakers == [views.cycle % pipeline.n]
        (i,) = speakers
        said = decode(command.say[i])
        expected = pipeline.world.message(i, views.cycle, tuple(pipeline.proposals[i].tolist()), said.settled)
        assert command.say[i] == expected
        spoken.append(said.settled)
        return command

    monkeypatch.setattr(Pipeline, "act", act)
    Match("mmdr", "static", seed=6, config=PARTIAL).run()
    assert len(spoken) > 200 and 0 < sum(spoken) < len(spoken)  # (both teams; settled and not)


def test_every_message_said_reaches_every_team_mate_within_range():
    """With one speaker a cycle, every team-mate within ``audio_cut_dist`` of the speaker when
    it speaks hears the message the next cycle, and nobody farther (counted over a match)."""
    from soccer_sim.perception.audio import AudioParams

    class Recorder:
        observation_modes = ("partial",)

        def __init__(self) -> None:
            self.inner = resolve_team("mmdr")[0]
            self.said: dict[int, tuple[int, str]] = {}
            self.heard: dict[int, list[tuple]] = {}

        def reset(self, side_info, config, rng):
            self.inner.reset(side_info, config, rng)

        def act(self, views):
            self.heard[views.cycle] = [tuple(row) for row in views.heard_mates]
            command = self.inner.act(views)
            (speaker,) = [i for i, text in enumerate(command.say) if text is not None]
            self.said[views.cycle] = (speaker, command.say[speaker])
            return command

    team = Recorder()
    match = Match(team, "static", seed=2, config=MatchConfig(observation=ObservationConfig("partial"),
                                                              max_cycles=300))
    match.start()
    cut = AudioParams().audio_cut_dist
    positions = {}
    while match.state.cycle < 299:
        positions[match.state.cycle] = match.state.pos[:11].copy()  # (where the players are as they speak)
        match.step()
    expected = delivered = 0
    for cycle, (speaker, text) in team.said.items():
        if cycle + 1 not in team.heard:
            continue
        pos = positions[cycle]
        for listener, row in enumerate(team.heard[cycle + 1]):
            near = listener != speaker and np.hypot(*(pos[listener] - pos[speaker])) <= cut
            got = (speaker, text) in row
            assert got == near, (cycle, speaker, listener)
            expected += near
            delivered += got
    assert delivered == expected > 2000


def test_players_who_speak_in_turns_agree_on_their_roles():
    """Under partial observation the believed role conflicts stay under 5 % of play-on cycles."""
    result = run_match("mmdr", "counter-442", seed=4, config=MatchConfig(observation=ObservationConfig("partial"),
                                                                          max_cycles=1000))
    stats = result.statistics[0].reported
    assert stats["role_conflict_share"] < 0.05 and stats["all_follow_one_share"] > 0.8


def test_under_full_observation_nobody_speaks():
    match = Match("mmdr", "static", seed=6, config=MatchConfig(max_cycles=50))
    match.start()
    for _ in range(49):
        match.step()
    assert match.teams[0].pipeline.command.say is None


@pytest.mark.parametrize("point, keeper_goes", [((-51.5, 0.0), True), ((-36.5, 19.0), True),
                                                 ((-52.55, 0.0), False), ((-35.0, 0.0), False),
                                                 ((-51.5, 20.7), False)])
def test_the_goalkeeper_comes_out_only_for_a_ball_it_wins_inside_our_area(point, keeper_goes):
    """:func:`~agents.teams.pipeline_kernels.ball_player` on a belief whose race has our
    goalkeeper first (cycle 2, the opponents at 20) at ``point`` and outfield player 1 next."""
    from agents.teams.pipeline_kernels import ball_player

    team, _ = resolve_team("mmdr")
    match = Match(team, "static", seed=1, config=MatchConfig(max_cycles=10))
    match.start()
    pipeline = team.pipeline
    model = pipeline.model
    assert model.half_length == 52.5 and model.penalty_area_length == 16.5 and model.penalty_area_half_width == 20.16
    pipeline.our_first[0] = 0
    pipeline.our_cycles[0] = 30
    pipeline.our_cycles[0, 0], pipeline.our_cycles[0, 1] = 2, 5
    pipeline.our_points[0, 0] = point
    pipeline.their_cycle[0] = 20
    pipeline.named_ball[0] = -1
    assert ball_player(pipeline.state, 0) == (0 if keeper_goes else 1)


def test_a_shared_assignment_leaves_no_player_disagreeing():
    """TeamStyle.shared_assignment (the perfect-agreement ablation): every player follows the
    first outfield player's belief's assignment, so no role is ever claimed twice."""
    from agents.teams.formation_team import FormationTeam
    from agents.teams.style import TeamStyle

    home = FormationTeam("mmdr", TeamStyle(shared_assignment=True))
    result = run_match(home, "counter-442", seed=4, config=MatchConfig(observation=ObservationConfig("partial"),
                                                                        max_cycles=400))
    stats = result.statistics[0].reported
    assert stats["role_conflict_share"] == 0.0 and stats["all_follow_one_share"] == 1.0
    assert home.pipeline.turns.followed.shape[1] == 0  # (no proposals said: nothing to agree on)


def test_the_built_in_factories_take_style_fields_as_options():
    from agents.teams.builtin import counter_442_team, mmdr_team

    assert mmdr_team(shared_assignment=True).style.shared_assignment
    assert counter_442_team(shared_assignment=True).style.system == "4-4-2"
    with pytest.raises(TypeError, match="not a TeamStyle field: sharing"):
        mmdr_team(sharing=True)


@pytest.mark.parametrize("agreement", ["speaker", "own"])
def test_each_agreement_follows_what_it_names(agreement, monkeypatch):
    """``speaker``: every proposal said is settled; ``own``: no proposal is kept, each player
    follows its own (the turns still carry the world information)."""
    from agents.messages import decode
    from agents.teams.builtin import mmdr_team
    from agents.teams.pipeline import Pipeline

    settled = []
    original = Pipeline.act

    def act(pipeline, views):
        command = original(pipeline, views)
        settled.extend(decode(text).settled for text in command.say if text is not None)
        if agreement == "own" and pipeline.style.agreement == "own":
            np.testing.assert_array_equal(pipeline.followed[pipeline.outfield], pipeline.proposals[pipeline.outfield])
        return command

    monkeypatch.setattr(Pipeline, "act", act)
    home = mmdr_team(agreement=agreement)
    run_match(home, "counter-442", seed=3, config=MatchConfig(observation=ObservationConfig("partial"),
                                                              max_cycles=200))
    assert len(settled) > 300
    if agreement == "speaker":
        assert home.pipeline.turns.followed.shape[1] == 10 and all(settled[::2])  # (home speaks first)
    else:
        assert home.pipeline.turns.followed.shape[1] == 0


def test_an_unknown_agreement_is_a_clear_error():
    from agents.teams.builtin import mmdr_team

    with pytest.raises(ValueError, match="agreement must be one of 'settled', 'speaker', 'own', got 'vote'"):
        mmdr_team(agreement="vote")
