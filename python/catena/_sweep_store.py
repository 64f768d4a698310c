# SPDX-License-Identifier: MIT
"""A sweep's results on disk: a journal of completed batches, then points.csv in point order.

DIR/journal.csv starts with one line "#catena-sweep-journal 1 <spec digest>", then holds one block
per completed batch: its CSV rows (consecutive points), then a line "#batch <first> <count>". The
client appends a block once per finished task and fsyncs it, so a killed client loses at most the
batch it was writing: a block without its "#batch" line is cut off when the journal is reopened.
Rerunning the same SPEC into DIR computes only the points no block holds; a journal of another
SPEC (digest) is refused. Memory is flat: a byte per point and a few numbers per block.
"""

import csv
import fcntl
import os
from typing import Iterator

import numpy

from ._catena import InvalidInput

_MAGIC = "#catena-sweep-journal 1"


class Store:
    def __init__(self, directory: str, digest: str, points: int, header: list[str]):
        self.directory, self.points, self.header = directory, points, header
        try:
            os.makedirs(directory, exist_ok=True)
        except OSError as error:
            raise InvalidInput(f"--out {directory}: cannot create the directory: {error.strerror}") from None
        self.path = os.path.join(directory, "journal.csv")
        self.done = numpy.zeros(points, dtype=bool)
        self.blocks: list[tuple[int, int, int, int]] = []  # (first point, count, offset, length)
        try:
            self.file = open(self.path, "a+b")
        except OSError as error:
            raise InvalidInput(f"--out {directory}: cannot write {self.path}: {error.strerror}") from None
        try:
            fcntl.flock(self.file, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            self.file.close()
            raise InvalidInput(f"--out {directory}: another sweep is writing into it now") from None
        self._open(digest)

    def _open(self, digest: str) -> None:
        self.file.seek(0)
        first = self.file.readline().decode(errors="replace").rstrip("\n")
        expected = f"{_MAGIC} {digest}"
        if not first:
            self.file.truncate(0)
            self._write(f"{expected}\n{','.join(self.header)}\n".encode())
            self.resumed = 0
            return
        if not first.startswith(_MAGIC):
            raise InvalidInput(f"--out {self.directory}: {self.path} is not a sweep journal; choose another directory")
        if first != expected:
            raise InvalidInput(f"--out {self.directory}: holds a sweep of another SPEC (or another scene, axes or "
                               "outputs) than this one; resume only with the same SPEC, or choose another directory")
        self.file.readline()  # the column names
        block_start = self.file.tell()
        while True:
            line = self.file.readline()
            if not line.endswith(b"\n"):
                break  # end of file, or a line cut by a kill
            if line.startswith(b"#batch "):
                first_point, count = (int(v) for v in line.split()[1:3])
                end = self.file.tell()
                self.blocks.append((first_point, count, block_start, end - len(line) - block_start))
                self.done[first_point:first_point + count] = True
                block_start = end
        self.file.truncate(block_start)  # an unfinished block is dropped: its points run again
        self.resumed = int(self.done.sum())

    def _write(self, data: bytes) -> None:
        self.file.seek(0, os.SEEK_END)
        self.file.write(data)
        self.file.flush()
        os.fsync(self.file.fileno())

    def missing_runs(self) -> Iterator[tuple[int, int]]:
        """(first, count) of each run of consecutive points not yet written, in order."""
        missing = numpy.flatnonzero(~self.done)
        if missing.size == 0:
            return
        breaks = numpy.flatnonzero(numpy.diff(missing) != 1)
        starts = [0] + [int(b) + 1 for b in breaks]
        ends = [int(b) for b in breaks] + [int(missing.size) - 1]
        for s, e in zip(starts, ends):
            yield int(missing[s]), int(missing[e] - missing[s] + 1)

    def append(self, first: int, count: int, rows: str) -> None:
        """Writes the block of points first..first+count-1 (once: a second write is a bug)."""
        if self.done[first:first + count].any():
            raise RuntimeError(f"sweep: points {first}..{first + count - 1} written twice")
        data = rows.encode()
        offset = self.file.seek(0, os.SEEK_END)
        self._write(data + f"#batch {first} {count}\n".encode())
        self.blocks.append((first, count, offset, len(data)))
        self.done[first:first + count] = True

    def assemble(self) -> str:
        """DIR/points.csv: the header and every block in point order (written to a temporary file,
        then renamed: a reader never sees half a table). Returns its path."""
        if not self.done.all():
            raise RuntimeError("sweep: assemble() before every point is written")
        path = os.path.join(self.directory, "points.csv")
        partial = path + ".partial"
        with open(partial, "wb") as out:
            out.write((",".join(self.header) + "\n").encode())
            for _, _, offset, length in sorted(self.blocks):
                self.file.seek(offset)
                out.write(self.file.read(length))
            out.flush()
            os.fsync(out.fileno())
        os.replace(partial, path)
        return path

    def close(self) -> None:
        self.file.close()


def status_counts(path: str, solvers: list[str]) -> tuple[dict[str, dict[str, int]], int]:
    """{solver: {status: points}} and the number of points with an error, streamed from points.csv."""
    counts: dict[str, dict[str, int]] = {s: {} for s in solvers}
    errors = 0
    with open(path, newline="") as file:
        reader = csv.reader(file)
        header = next(reader)
        where = {s: header.index(f"{s}.status") for s in solvers}
        error_column = header.index("error")
        for row in reader:
            for solver, column in where.items():
                counts[solver][row[column]] = counts[solver].get(row[column], 0) + 1
            errors += bool(row[error_column])
    return counts, errors
