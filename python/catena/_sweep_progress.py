# SPDX-License-Identifier: MIT
"""A sweep's progress on stderr: points done / total, rate and ETA. On a terminal one line that
updates in place (at most 5 times a second); otherwise (a log, CI) a line every 10 s."""

import sys
import time
from typing import Any, Optional


def _duration(seconds: float) -> str:
    seconds = int(round(seconds))
    hours, rest = divmod(seconds, 3600)
    return f"{hours}:{rest // 60:02d}:{rest % 60:02d}" if hours else f"{rest // 60}:{rest % 60:02d}"


class Progress:
    def __init__(self, total: int, enabled: Optional[bool] = None, stream: Any = None):
        self.stream = stream or sys.stderr
        self.tty = bool(getattr(self.stream, "isatty", lambda: False)())
        self.enabled = self.tty if enabled is None else enabled
        self.total, self.done = total, 0
        self.start = self.last = time.monotonic()
        self.period = 0.2 if self.tty else 10.0

    def line(self) -> str:
        elapsed = time.monotonic() - self.start
        rate = self.done / elapsed if elapsed > 0 else 0.0
        eta = _duration((self.total - self.done) / rate) if rate > 0 else "?"
        percent = 100.0 * self.done / self.total if self.total else 100.0
        return (f"sweep: {self.done}/{self.total} points ({percent:.1f} %), {rate:.1f} points/s, "
                f"elapsed {_duration(elapsed)}, ETA {eta}")

    def update(self, count: int) -> None:
        self.done += count
        now = time.monotonic()
        if self.enabled and (now - self.last >= self.period or self.done == self.total):
            self.last = now
            self._show()

    def _show(self) -> None:
        if self.tty:
            self.stream.write("\r\033[K" + self.line())
        else:
            self.stream.write(self.line() + "\n")
        self.stream.flush()

    def finish(self) -> None:
        if self.enabled and self.tty:
            self.stream.write("\n")
            self.stream.flush()
