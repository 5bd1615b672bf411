"""Where the reference kit's build of rcssserver and helios-base lies (``$RCSS_HOME``).

The kit's ``build.sh`` (``../shared/reference/rcssserver/build.sh`` beside the project)
installs the server into ``$RCSS_HOME/install`` (``bin/rcssserver``, its libraries in
``lib``) and builds helios-base in ``$RCSS_HOME/src/helios-base/build/bin`` (``start.sh``
starts a full team). ``$RCSS_HOME`` defaults to ``~/.cache/rcss-reference``.
:meth:`RcssInstall.find` resolves that layout; :meth:`RcssInstall.require_server` and
:meth:`RcssInstall.require_helios` say in one line what is missing and how to build it.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path

from rcss_bridge.errors import BridgeError

DEFAULT_HOME = "~/.cache/rcss-reference"
"""The kit's default ``$RCSS_HOME``."""

BUILD_SCRIPT = "../shared/reference/rcssserver/build.sh"
"""The kit's build script, as the project's documentation names it."""

HELIOS_TEAM = "helios-base"
"""The name the team the kit builds (:attr:`RcssInstall.helios_bin`) plays under."""


class MissingBuild(BridgeError, FileNotFoundError):
    """The server or helios-base is not built where the kit puts it."""


@dataclass(frozen=True)
class RcssInstall:
    """The kit's build under ``home`` (``$RCSS_HOME``)."""

    home: Path

    @classmethod
    def find(cls, home: str | os.PathLike | None = None) -> RcssInstall:
        """The build under ``home``, else ``$RCSS_HOME``, else :data:`DEFAULT_HOME`."""
        chosen = home if home is not None else os.environ.get("RCSS_HOME") or DEFAULT_HOME
        return cls(Path(os.path.expanduser(os.fspath(chosen))).absolute())

    @property
    def server(self) -> Path:
        """The server's binary."""
        return self.home / "install" / "bin" / "rcssserver"

    @property
    def libraries(self) -> Path:
        """The server's and librcsc's shared libraries (``LD_LIBRARY_PATH``)."""
        return self.home / "install" / "lib"

    @property
    def helios_bin(self) -> Path:
        """helios-base's build directory (``start.sh``, ``sample_player``, its formations)."""
        return self.home / "src" / "helios-base" / "build" / "bin"

    def require_server(self) -> Path:
        """The server's binary; a :class:`MissingBuild` saying how to build it when absent."""
        if not os.access(self.server, os.X_OK):
            raise MissingBuild(f"rcssserver is not built in {self.home} (no {self.server}): build it with "
                               f"{BUILD_SCRIPT} --server-only, or give its RCSS_HOME with --rcss-home")
        return self.server

    def require_helios(self) -> Path:
        """helios-base's ``start.sh``; a :class:`MissingBuild` saying how to build it when absent."""
        start = self.helios_bin / "start.sh"
        if not os.access(start, os.X_OK) or not os.access(self.helios_bin / "sample_player", os.X_OK):
            raise MissingBuild(f"helios-base is not built in {self.home} (no {start}): build it with "
                               f"{BUILD_SCRIPT} (about 17 minutes), or give its RCSS_HOME with --rcss-home")
        return start
