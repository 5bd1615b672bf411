"""The default layout of a replay in the rerun viewer: the field beside the score and the
events."""

from __future__ import annotations

from soccer_sim.config import FieldConfig
from soccer_sim.replay.field import GRASS_COLOUR

MESH_PATHS = ("/world/home/roles/triangulation", "/world/away/roles/triangulation")
"""The formation meshes, hidden when a replay opens unless asked for."""


def default_blueprint(field: FieldConfig, formation_meshes: bool = False):
    """A blueprint with the 2-D field view (bounded to the field and its margin) on the left
    and, on the right, the score, possession and stamina series above the event log.

    The field view's origin is the root, so the recording's ``/world`` transform (which
    mirrors y, see :data:`soccer_sim.replay.recorder.VIEW_SCALE`) applies and +y is drawn
    upwards. Its background is the grass colour; the grass image takes no clicks. The
    formation meshes are hidden unless ``formation_meshes`` (the viewer's visibility toggle
    shows them).
    """
    import rerun.blueprint as rrb

    hl, hw, m = field.length / 2.0, field.width / 2.0, field.margin
    overrides = {"/world/field/grass": rrb.EntityBehavior(interactive=False)}
    if not formation_meshes:
        overrides.update({path: rrb.EntityBehavior(visible=False) for path in MESH_PATHS})
    return rrb.Blueprint(
        rrb.Horizontal(
            rrb.Spatial2DView(origin="/", contents="/world/**", name="field", overrides=overrides,
                              background=rrb.Background(kind="SolidColor", color=GRASS_COLOUR),
                              visual_bounds=rrb.VisualBounds2D(x_range=[-hl - m, hl + m], y_range=[-hw - m, hw + m])),
            rrb.Vertical(
                rrb.TimeSeriesView(origin="/stats/score", name="score"),
                rrb.TimeSeriesView(origin="/stats/possession", name="possession (home's share)"),
                rrb.TimeSeriesView(origin="/stats/stamina", name="mean stamina"),
                rrb.TextLogView(origin="/events", name="events"),
            ),
            column_shares=[3, 2],
        ),
        collapse_panels=True,
    )
