"""Sharing one results file between several runs: leases on the matches being played.

Before a run hands a match to its workers it *claims* it: in one short write transaction
(``BEGIN IMMEDIATE``) it skips matches already stored or leased by another live run and writes
a lease (the match's key, the run's owner id ``host:pid:random`` and an expiry time) on the
next free one. The lease is released in the transaction that stores the match, renewed by a
background thread while the run lives, and given up when the run ends. A run that was killed
leaves leases that expire (at once when its process is known to be gone, on the same host), so
a resumed run plays them. Two runs of the same command on one file therefore split its matches
instead of both playing everything.

Times are wall-clock seconds (``time.time()``): the runs sharing a file share its machine.
"""

from __future__ import annotations

import os
import secrets
import socket
import sqlite3
import threading
import time
from collections import deque
from collections.abc import Callable, Iterable
from typing import Protocol

from experiments.results.store import ResultStore, StorageError

LEASE_SECONDS = 60.0
"""How long a lease lasts without renewal: a run that stops renewing (killed on another host,
or suspended) loses its matches to other runs after this long."""

RENEW_EVERY = LEASE_SECONDS / 4
"""How often a live run renews its leases."""

Key = tuple[str, str, int]


class Keyed(Protocol):
    """What a lease is taken on: anything with a match key (e.g. a MatchSpec)."""

    @property
    def key(self) -> Key: ...


def new_owner() -> str:
    """A run's owner id, ``host:pid:random`` (unique even when a pid is reused)."""
    return f"{socket.gethostname()}:{os.getpid()}:{secrets.token_hex(4)}"


def owner_is_gone(owner: str) -> bool:
    """True when ``owner`` is a process of this host that no longer exists (its leases are void)."""
    host, _, rest = owner.partition(":")
    pid_text = rest.partition(":")[0]
    if host != socket.gethostname() or not pid_text.isdigit():
        return False
    try:
        os.kill(int(pid_text), 0)
    except ProcessLookupError:
        return True
    except (PermissionError, OverflowError):   # someone else's process, or not a pid: assume alive
        return False
    return False


class Leases:
    """The leases of one run (``owner``) on the matches of ``store``."""

    def __init__(self, store: ResultStore, owner: str | None = None, seconds: float = LEASE_SECONDS) -> None:
        self.store = store
        self.owner = owner or new_owner()
        self.seconds = seconds
        store.lease_owner = self.owner        # storing a match releases its lease in the same transaction
        self._stop = threading.Event()
        self._renewer: threading.Thread | None = None

    def claim(self, key: Key) -> str:
        """Try to lease ``key``: ``"claimed"`` (now ours), ``"stored"`` (already stored) or
        ``"elsewhere"`` (leased by another live run)."""
        now = time.time()
        try:
            with self.store.immediate() as db:
                if db.execute("SELECT 1 FROM matches WHERE home = ? AND away = ? AND seed = ? AND config_hash = ?",
                              (*key, self.store.config_hash)).fetchone():
                    return "stored"
                if self._held_elsewhere(db, key, now):
                    return "elsewhere"
                db.execute("INSERT OR REPLACE INTO leases VALUES (?, ?, ?, ?, ?)",
                           (*key, self.owner, now + self.seconds))
        except sqlite3.Error as exc:
            raise self._failure(exc) from None
        self._start_renewing()
        return "claimed"

    def held_elsewhere(self, keys: Iterable[Key]) -> set[Key]:
        """The keys among ``keys`` not stored and leased by another live run."""
        now = time.time()
        try:
            stored = self.store.keys()
            with self.store.immediate() as db:       # one consistent view of the leases
                return {key for key in keys if key not in stored and self._held_elsewhere(db, key, now)}
        except sqlite3.Error as exc:
            raise self._failure(exc) from None

    def _held_elsewhere(self, db: sqlite3.Connection, key: Key, now: float) -> bool:
        """Whether another run holds a live lease on ``key``: not expired, and its process not known gone."""
        lease = db.execute("SELECT owner, expires_at FROM leases WHERE home = ? AND away = ? AND seed = ?",
                           key).fetchone()
        return lease is not None and lease[0] != self.owner and lease[1] > now and not owner_is_gone(lease[0])

    def _failure(self, exc: sqlite3.Error) -> StorageError:
        return StorageError(f"{self.store.path}: cannot claim a match to play ({exc}); every match stored before "
                            "is kept; re-run the same command to resume")

    def release_all(self) -> None:
        """Stop renewing and give up every lease of this run (its unplayed matches become free)."""
        self._stop.set()
        if self._renewer is not None:
            self._renewer.join()
            self._renewer = None
        try:
            with self.store.immediate() as db:
                db.execute("DELETE FROM leases WHERE owner = ?", (self.owner,))
        except sqlite3.Error:
            pass                              # they expire on their own

    def _start_renewing(self) -> None:
        if self._renewer is None and not self._stop.is_set():
            self._renewer = threading.Thread(target=self._renew, name="soccer-sim-leases", daemon=True)
            self._renewer.start()

    def _renew(self) -> None:
        """Push this run's leases forward every RENEW_EVERY seconds (own connection: its own thread)."""
        db = sqlite3.connect(str(self.store.path), timeout=30.0)
        try:
            while not self._stop.wait(min(RENEW_EVERY, self.seconds / 4)):
                try:
                    with db:
                        db.execute("UPDATE leases SET expires_at = ? WHERE owner = ?",
                                   (time.time() + self.seconds, self.owner))
                except sqlite3.Error:
                    pass                      # tried again next time; a lost lease only costs a repeated match
        finally:
            db.close()


class ClaimQueue:
    """The matches of a run, handed out one at a time as they are claimed.

    A pool takes it as its queue of pending specs: truth (``bool``) claims the next free spec
    ahead of time, :meth:`popleft` hands it out. Specs stored by another run meanwhile are
    dropped (``on_stored`` is told), those leased by another live run are kept in
    :attr:`elsewhere` for the run to wait for."""

    def __init__(self, leases: Leases, specs: Iterable[Keyed],
                 on_stored: Callable[[Keyed], None] | None = None) -> None:
        self._leases = leases
        self._candidates = deque(specs)
        self._next: Keyed | None = None
        self._on_stored = on_stored
        self.elsewhere: list[Keyed] = []

    def _fill(self) -> None:
        while self._next is None and self._candidates:
            spec = self._candidates.popleft()
            outcome = self._leases.claim(spec.key)
            if outcome == "claimed":
                self._next = spec
            elif outcome == "elsewhere":
                self.elsewhere.append(spec)
            elif self._on_stored is not None:
                self._on_stored(spec)

    def __bool__(self) -> bool:
        self._fill()
        return self._next is not None

    def __len__(self) -> int:
        """At most this many specs are still to be handed out."""
        return len(self._candidates) + (self._next is not None)

    def popleft(self) -> Keyed:
        self._fill()
        if self._next is None:
            raise IndexError("no match left to claim")
        spec, self._next = self._next, None
        return spec

    def __iter__(self):
        while self:
            yield self.popleft()


POLL_SECONDS = 0.5
"""How often a run waiting for another run's matches looks at the file again."""


class SharedWork:
    """The matches of one run on a file other runs may share: the queues to play, then the
    wait for the matches other runs are playing.

    :meth:`queues` yields a :class:`ClaimQueue` whenever there is something to claim; once
    everything left is leased by other live runs it waits (without progress for at most
    ``wait`` seconds) until those are stored, or claims them when their leases lapse. What is
    still being played elsewhere after that is :attr:`unfinished`."""

    def __init__(self, store: ResultStore, specs: Iterable[Keyed], wait: float,
                 log: Callable[[str], None] | None = None) -> None:
        self.leases = Leases(store)
        self.store = store
        self._specs = list(specs)
        self._wait = wait
        self._log = log
        self.on_stored: Callable[[Keyed], None] | None = None
        """Told of every match found stored by another run."""
        self.by_others = 0
        """Matches of this run stored by other runs."""
        self.unfinished = 0
        """Matches still leased by another run when this one stopped waiting."""

    def queues(self) -> Iterable[ClaimQueue]:
        remaining = self._specs
        last_progress = time.monotonic()
        announced = False
        while remaining:
            queue = ClaimQueue(self.leases, remaining, self._stored)
            if queue:
                yield queue
                if len(queue):                    # the caller stopped early: nothing to wait for
                    return
                last_progress = time.monotonic()
            remaining = queue.elsewhere
            while remaining:
                held = self.leases.held_elsewhere(spec.key for spec in remaining)
                stored = self.store.keys()
                for spec in remaining:
                    if spec.key in stored:
                        self._stored(spec)
                        last_progress = time.monotonic()
                remaining = [spec for spec in remaining if spec.key not in stored]
                if any(spec.key not in held for spec in remaining):
                    break                         # a lease lapsed or was given up: claim it
                if remaining and time.monotonic() - last_progress >= self._wait:
                    self.unfinished = len(remaining)
                    return
                if remaining:
                    if not announced and self._log is not None:
                        self._log(f"waiting for {len(remaining)} match(es) being played by another run on "
                                  f"{self.store.path}")
                        announced = True
                    time.sleep(POLL_SECONDS)

    def _stored(self, spec: Keyed) -> None:
        self.by_others += 1
        if self.on_stored is not None:
            self.on_stored(spec)

    def __enter__(self) -> SharedWork:
        return self

    def __exit__(self, *exc) -> None:
        self.leases.release_all()
