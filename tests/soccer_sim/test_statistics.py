"""Match statistics' shared definitions: possession (``soccer_sim.analysis.possession``) and the
optional ``statistics()`` hook (``soccer_sim.team_hooks.ReportsStatistics``)."""

from __future__ import annotations

import numpy as np
import pytest

from soccer_sim import MatchConfig, run_match
from soccer_sim.analysis.possession import Possession
from soccer_sim.state import AWAY, HOME, PlayMode
from soccer_sim.team_hooks import ReportsStatistics
from soccer_sim.trivial_teams import ChaserTeam


def test_possession_counts_cycles_by_the_last_touchers_team() -> None:
    possession = Possession(home_players=3)
    assert possession.share(HOME) == possession.share(AWAY) == 0.0  # nobody has had the ball
    for toucher in (-1, 0, 2, 3, 7, -1, 1):  # rows 0-2 are home's, 3 and above away's
        possession.add(toucher)
    assert possession.cycles == [3, 2]
    assert possession.share(HOME) == pytest.approx(0.6) and possession.share(AWAY) == pytest.approx(0.4)
    assert possession.share() == possession.share(HOME)


class Touches:
    """Every cycle's last toucher and play mode."""

    def on_start(self, match) -> None:
        self.n, self.rows = match.state.sizes[0], []

    def on_cycle(self, match) -> None:
        self.rows.append((int(match.state.last_touch), int(match.state.play_mode)))

    def on_end(self, match) -> None:
        pass


def test_statistics_possession_counts_every_play_mode() -> None:
    touches = Touches()
    result = run_match("chaser", "chaser", seed=5, config=MatchConfig(max_cycles=400), recorders=[touches])
    touchers = np.array([t for t, _ in touches.rows])
    home, away = np.count_nonzero((touchers >= 0) & (touchers < touches.n)), np.count_nonzero(touchers >= touches.n)
    assert result.statistics[HOME].possession == home / (home + away)
    assert result.statistics[AWAY].possession == away / (home + away)
    in_play = [t for t, mode in touches.rows if mode == PlayMode.PLAY_ON and t >= 0]
    assert len(in_play) < home + away  # cycles outside play on counted too


def test_only_teams_with_a_statistics_method_report_figures() -> None:
    class Reporting(ChaserTeam):
        def statistics(self) -> dict[str, float]:
            return {"sprints": 3}

    assert isinstance(Reporting(), ReportsStatistics) and not isinstance(ChaserTeam(), ReportsStatistics)
    result = run_match(Reporting(), ChaserTeam(), config=MatchConfig(max_cycles=5))
    assert result.statistics[HOME].reported == {"sprints": 3.0} and result.statistics[AWAY].reported == {}
