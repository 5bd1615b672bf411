"""Per-player partial observation: rcssserver's ``see`` adapted to soccer-sim's point robots
(:mod:`.see`), when sees arrive (:func:`.params.see_cycles`), self-localisation
(:mod:`.localise`) and the say/hear channel (:mod:`.audio`). Self-contained: the match loop
does not use it yet."""

from soccer_sim.perception.audio import SAY_CHARACTERS, AudioChannel, AudioParams, Heard, check_message
from soccer_sim.perception.localise import SelfEstimate, field_flags, localise
from soccer_sim.perception.params import SeeParams, see_cycles
from soccer_sim.perception.see import (ANONYMOUS, FULL, TEAM_ONLY, UNSEEN, Sightings, body_directions,
                                       quantized_distance, see)
from soccer_sim.perception.view_width import KEEP, NARROW, NORMAL, WIDE

__all__ = ["ANONYMOUS", "FULL", "KEEP", "NARROW", "NORMAL", "SAY_CHARACTERS", "TEAM_ONLY", "UNSEEN", "WIDE",
           "AudioChannel", "AudioParams", "Heard",
           "SeeParams", "SelfEstimate", "Sightings", "body_directions", "check_message", "field_flags", "localise",
           "quantized_distance", "see", "see_cycles"]
