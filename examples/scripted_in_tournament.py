"""Enter the scripted team (written for the environment) in a tournament against built-in teams.

Run: python examples/scripted_in_tournament.py
The same from the shell: soccer-sim tournament --teams static,greedy,examples.scripted_team:ScriptedTeam --games 2
"""

import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))  # the checkout, for `examples.*`

from experiments.cli import main  # noqa: E402

if __name__ == "__main__":
    sys.exit(main(["tournament", "--teams", "static,greedy,examples.scripted_team:ScriptedTeam", "--games", "2",
                   "--out", "scripted-tournament.sqlite", "--tables", "scripted-tournament-tables"]))
