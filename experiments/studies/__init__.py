"""Studies run by ``soccer-sim experiment NAME``: each module exposes ``add_arguments(parser)``
and ``run(args) -> int`` and is listed in :data:`experiments.commands.experiment.STUDIES`."""
