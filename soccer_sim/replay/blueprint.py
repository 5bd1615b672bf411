"""The default layout of a replay in the rerun viewer: the field beside the score and the
events."""

from __future__ import annotations

from soccer_sim.config import FieldConfig


def default_blueprint(field: FieldConfig):
    """A blueprint with the 2-D field view (bounded to the field and its margin) on the left
    and, on the right, the score, possession and stamina series above the event log."""
    import rerun.blueprint as rrb

    hl, hw, m = field.length / 2.0, field.width / 2.0, field.margin
    return rrb.Blueprint(
        rrb.Horizontal(
            rrb.Spatial2DView(origin="/world", name="field",
                              visual_bounds=rrb.VisualBounds2D(x_range=[-hl - m, hl + m], y_range=[-hw - m, hw + m])),
            rrb.Vertical(
                rrb.TimeSeriesView(origin="/stats/score", name="score"),
                rrb.TimeSeriesView(origin="/stats/possession", name="possession (share of play-on cycles)"),
                rrb.TimeSeriesView(origin="/stats/stamina", name="mean stamina"),
                rrb.TextLogView(origin="/events", name="events"),
            ),
            column_shares=[3, 2],
        ),
        collapse_panels=True,
    )
