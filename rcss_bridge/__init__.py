"""The bridge to the real RoboCup 2D server (rcssserver 19): the project's teams as its clients.

This package holds the client layer, the views and the command translation (``docs/bridge.md``):

* :mod:`~rcss_bridge.client`: one team's players and online coach from one process in
  synchronous mode (:class:`TeamClient`), with its own step counter, time-outs and a clean
  ``(bye)``; :mod:`~rcss_bridge.connection` is one UDP connection.
* :mod:`~rcss_bridge.messages` and :mod:`~rcss_bridge.params`: the server's messages as typed
  records, its parameters as the project's ``MatchConfig`` and ``PlayerType``.
* :mod:`~rcss_bridge.views_builder` (with :mod:`~rcss_bridge.localisation`,
  :mod:`~rcss_bridge.landmarks` and :mod:`~rcss_bridge.play_modes`): each player's
  ``PlayerViews`` row from what the server told that player, in the team's frame.
* :mod:`~rcss_bridge.commands` (with :mod:`~rcss_bridge.body_control`): a team's
  ``TeamCommand`` as each player's one body command, ``turn_neck`` and say
  (:class:`CommandTranslator`), and the coach's player types.
* :mod:`~rcss_bridge.transcripts`: recorded exchanges, one datagram per JSON line.

It imports :mod:`soccer_sim` (the project's configuration, views and self-localisation
formula) and never ``agents`` or ``experiments``.
"""

from rcss_bridge.body_control import ServerRules
from rcss_bridge.client import ClientSettings, Step, TeamClient, command_datagram
from rcss_bridge.commands import CommandTranslator, PlayerBodies
from rcss_bridge.errors import BridgeError, CommandError, ProtocolError, ServerError, TeamFailure, TeamTooSlow
from rcss_bridge.orders import PlayerOrder
from rcss_bridge.params import ServerParameters
from rcss_bridge.views_builder import ViewsBuilder

__all__ = [
    "BridgeError", "ClientSettings", "CommandError", "CommandTranslator", "PlayerBodies", "PlayerOrder",
    "ProtocolError", "ServerError", "ServerParameters", "ServerRules", "Step", "TeamClient", "TeamFailure",
    "TeamTooSlow", "ViewsBuilder", "command_datagram",
]
