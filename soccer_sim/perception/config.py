"""How a match's players perceive the world: :class:`ObservationConfig`, part of ``MatchConfig``.

``mode="full"`` (the default) gives each team the exact world state in one
:class:`~soccer_sim.team.TeamView` per cycle, as soccer-sim always has. ``mode="partial"`` gives
each player its own noisy, range-limited observation (:mod:`soccer_sim.perception.views`) with
rcssserver's see model (:class:`~soccer_sim.perception.params.SeeParams`) and its say/hear
channel (:class:`~soccer_sim.perception.audio.AudioParams`); see ``docs/simulator.md`` §12-14.
"""

from __future__ import annotations

from dataclasses import dataclass
from dataclasses import field as default_of

from soccer_sim.config_checks import ConfigError
from soccer_sim.perception.audio import AudioParams
from soccer_sim.perception.params import SeeParams

OBSERVATION_MODES = ("full", "partial")
"""The values of :attr:`ObservationConfig.mode`."""


@dataclass(frozen=True)
class ObservationConfig:
    """What the teams perceive: the whole state (``full``) or per-player sees and messages (``partial``)."""

    mode: str = "full"
    """``"full"``: one exact team view per cycle (no messages). ``"partial"``: per-player
    observations by rcssserver's see model, self-localisation and the say/hear channel."""
    see: SeeParams = default_of(default_factory=SeeParams)
    """The see model's parameters (used under ``partial``)."""
    audio: AudioParams = default_of(default_factory=AudioParams)
    """The say/hear channel's parameters (used under ``partial``)."""

    def validate(self) -> None:
        if self.mode not in OBSERVATION_MODES:
            raise ConfigError(f"ObservationConfig.mode must be one of {', '.join(OBSERVATION_MODES)}, "
                              f"got {self.mode!r}")
        if not isinstance(self.see, SeeParams):
            raise ConfigError(f"ObservationConfig.see must be a SeeParams, got {type(self.see).__name__}")
        if not isinstance(self.audio, AudioParams):
            raise ConfigError(f"ObservationConfig.audio must be an AudioParams, got {type(self.audio).__name__}")

    @property
    def partial(self) -> bool:
        """Whether players observe partially (``mode == "partial"``)."""
        return self.mode == "partial"
