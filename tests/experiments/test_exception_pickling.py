"""Every exception the project defines survives pickling (a worker process sends it to its
parent): same type, same message, same attributes."""

from __future__ import annotations

import importlib
import pickle
import pkgutil

import pytest

PACKAGES = ("soccer_sim", "formations", "agents", "experiments")

#: Exception class (module.Name) -> constructor arguments of an example.
EXAMPLES: dict[str, tuple] = {
    "soccer_sim.team.TeamError": ("red", "act() raised ValueError: x", 3),
    "soccer_sim.registry.TeamNotFoundError": ("unknown team 'x'",),
    "soccer_sim.env.checkpoints.CheckpointError": ("checkpoint 'm.zip': no such file",),
    "soccer_sim.config_checks.ConfigError": ("MatchConfig.max_cycles must be positive",),
    "soccer_sim.physics.PymunkChangedError": ("no Buffer",),
    "soccer_sim.state.StateError": ("WorldState.vel must have shape (4, 2), got (3, 2)",),
    "formations.errors.FormationError": ("a.json", "sample 3 is outside the field", "formation 'attack'"),
    "agents.assignment.errors.AssignmentError": ("NaN in robots",),
    "agents.skills.model.SkillInputError": ("horizon must be positive",),
    "experiments.errors.StudyArgumentError": ("lambdas: bad",),
    "experiments.limits.OutOfRange": ("--etsp-sizes: each value must be an integer from 2 to 100000 (agents), got 1",),
    "soccer_sim.recorder.RecorderError": ("recorders must be a list or other iterable of recorders, got int",),
    "soccer_sim.match.SeedError": ("seed must be a non-negative integer, got -1",),
    "soccer_sim.setup.SetupTypeError": ("config must be a MatchConfig, got str",),
    "experiments.errors.ExperimentError": ("a run cannot start",),
    "agents.errors.AgentsError": ("an assigner refuses its input",),
    "agents.roles.errors.RoleError": ("unknown role assigner 'mmdx'",),
    "agents.messages.MessageError": ("ball x must be finite and within [-64.0, 64.0], got 70.0",),
    "formations.errors.FormationInputError": ("ball must be a point (2,) or points (k, 2)",),
    "formations.errors.UnknownRoleError": ("no role numbered 12",),
    "soccer_sim.errors.SoccerSimError": ("the simulator refuses its input",),
    "soccer_sim.replay.recorder.ReplayError": ("replays need rerun-sdk: pip install rerun-sdk",),
    "soccer_sim.rcg.recorder.RcgError": ("m.rcg, line 3: unknown line",),
    "soccer_sim.scenarios.parts.ScenarioError": ("home.goalie", "index 4 is beyond the side's 3 players"),
    "experiments.results.store.ResultsError": ("r.sqlite: not writable",),
    "experiments.results.store.StorageError": ("r.sqlite: cannot store a match (database or disk is full)",),
    "experiments.results.export.ExportError": ("needs pyarrow",),
    "experiments.runner.worker.MatchTimeout": (2.5,),
    "experiments.runner.local.MatchFailed": ("WorkerDied: the worker process ended with exit code 0", 1),
    "experiments.runner.ray_cluster.RayUnavailable": ("no ray",),
    "experiments.commands.run_options.RunInputError": ("--teams: unknown team",),
    "experiments.studies.transfer_report.TransferInputError": ("--out-real r.sqlite: no such results file",),
    "experiments.errors.ParameterError": ("record_every", "must be at least 1, got 0"),
    "experiments.runner.run.MixedCodeVersions": ("r.sqlite", "0.0.1+old", "0.2.0+abc"),
    "experiments.runner.run.MixedCodeWarning": ("r.sqlite", "0.0.1+old", "0.2.0+abc"),
    "experiments.runner.run.RunStopped": ("run stopped: 5 of the 20 matches finished so far failed",),
    "experiments.benchmarks.grid_assignment.TotalsDiffer": ("lazy 41 != all pairs 40 on instance 3",),
    "experiments.benchmarks.startup._RunFailed": ("play exited with status 2: error: unknown team",),
}


def project_exceptions() -> dict[str, type]:
    """Every Exception subclass defined in the project's modules."""
    found = {}
    for package_name in PACKAGES:
        package = importlib.import_module(package_name)
        for info in pkgutil.walk_packages(package.__path__, package_name + "."):
            try:
                module = importlib.import_module(info.name)
            except ImportError:                        # an optional dependency
                continue
            for value in vars(module).values():
                if (isinstance(value, type) and issubclass(value, BaseException)
                        and value.__module__ == module.__name__):
                    found[f"{value.__module__}.{value.__qualname__}"] = value
    return found


def test_every_project_exception_has_an_example() -> None:
    missing = sorted(set(project_exceptions()) - set(EXAMPLES))
    assert not missing, f"add an example of {missing} to EXAMPLES"


@pytest.mark.parametrize("name", sorted(EXAMPLES))
def test_exception_survives_pickling(name: str) -> None:
    module_name, _, class_name = name.rpartition(".")
    cls = getattr(importlib.import_module(module_name), class_name)
    error = cls(*EXAMPLES[name])
    copy = pickle.loads(pickle.dumps(error))
    assert type(copy) is cls
    assert str(copy) == str(error)
    assert vars(copy) == vars(error)


def test_every_experiments_error_derives_from_the_root_and_keeps_its_base() -> None:
    from agents.assignment import AssignmentError
    from experiments.errors import ExperimentError, StudyArgumentError

    errors = {name: cls for name, cls in project_exceptions().items() if name.startswith("experiments.")}
    assert len(errors) >= 11
    assert not [name for name, cls in errors.items() if not issubclass(cls, ExperimentError)]
    assert issubclass(StudyArgumentError, ValueError)
    grid = importlib.import_module("experiments.benchmarks.grid_assignment")
    assert issubclass(grid.TotalsDiffer, AssignmentError)


def test_studies_and_benchmarks_share_one_argument_error() -> None:
    from experiments.errors import StudyArgumentError

    for module in ("experiments.studies.incremental", "experiments.studies.distributed",
                   "experiments.benchmarks.assignment"):
        found = {value for value in vars(importlib.import_module(module)).values()
                 if isinstance(value, type) and issubclass(value, BaseException) and "Argument" in value.__name__}
        assert found == {StudyArgumentError}, module
