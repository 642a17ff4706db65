"""Safe input and output: what a careful Unix tool does with files it did not make.

- Reading: only regular files, at most :data:`MAX_INPUT_BYTES`, never blocking on a FIFO; a
  UTF-8 byte-order mark is accepted; TOML nested deeper than :data:`MAX_DEPTH` is refused in
  one line (instead of a RecursionError).
- Writing: atomically beside the target, through symlinks to their target, never onto a
  device, FIFO or directory; the temporary file has a unique name and is the only file a
  writer ever removes; a new file gets the mode an editor would give it (the umask applies),
  an existing file keeps its mode.
- Showing: user text (titles, names, paths, echoed values) is data. :func:`printable` shows
  control characters escaped, :func:`clip` bounds an echoed value, :func:`plain` makes a
  rich/textual ``Text`` that is never read as markup.

This module imports nothing heavy: the batch path uses it.
"""

import os
import stat
import sys
import tomllib
from pathlib import Path
from typing import Any

from advisor.core.errors import InputError

#: A requirement file is kilobytes; anything above this is not one.
MAX_INPUT_BYTES = 1 << 20
#: Tables and arrays nest two or three levels in a requirement; 32 is far beyond any.
MAX_DEPTH = 32
#: An echoed value (a title, a string given for a number) is cut to about this length.
ECHO_CHARS = 80

_BIDI = {chr(c) for c in (*range(0x202A, 0x202F), *range(0x2066, 0x206A))}


class OutputError(InputError):
    """The report cannot be written where it was asked to go (exit 2, one line)."""


# ------------------------------------------------------------------ showing user text
def printable(text: str, newlines: bool = True) -> str:
    """``text`` with control characters (and bidirectional overrides) shown escaped, so an
    ANSI escape in a title is printed as ``\\x1b[2J`` and never clears the terminal. Line
    breaks and tabs are kept unless ``newlines`` is false (a one-line echo)."""
    if text.isprintable():
        return text
    import unicodedata  # only for text that is not printable (rare): not on every run

    keep = "\n\t" if newlines else ""
    return "".join(
        ch.encode("unicode_escape").decode("ascii")
        if (unicodedata.category(ch) == "Cc" and ch not in keep) or ch in _BIDI
        else ch
        for ch in text
    )


def clip(text: str, limit: int = ECHO_CHARS) -> str:
    """At most about ``limit`` characters: a 10 MB title must not become a 10 MB line."""
    if len(text) <= limit:
        return text
    return f"{text[: limit - 1]}… ({len(text):,} characters)"


def show(text: Any, limit: int = ECHO_CHARS) -> str:
    """A user string as it may be echoed in a message: controls escaped, then clipped."""
    s = str(text)
    head = printable(s[: limit * 4], newlines=False)
    if len(s) <= limit * 4 and len(head) <= limit:
        return head
    return f"{head[: limit - 1]}… ({len(s):,} characters)"


def show_repr(text: str, limit: int = ECHO_CHARS) -> str:
    """A user string quoted as Python shows it (controls escaped by ``repr``), cut to about
    ``limit`` characters with its real length said."""
    r = repr(text[: limit * 2])
    if len(text) <= limit * 2 and len(r) <= limit:
        return r
    return f"{r[: limit - 1]}…{r[0]} ({len(text):,} characters)"


def plain(text: Any, style: str = "") -> Any:
    """A rich ``Text`` of user text: never parsed as markup or emoji, controls escaped."""
    from rich.text import Text

    return Text(printable(str(text)), style=style)


# ------------------------------------------------------------------ reading
def _kind_of(mode: int) -> str:
    if stat.S_ISDIR(mode):
        return "a directory"
    if stat.S_ISFIFO(mode):
        return "a FIFO"
    if stat.S_ISCHR(mode) or stat.S_ISBLK(mode):
        return "a device"
    if stat.S_ISSOCK(mode):
        return "a socket"
    return "not a regular file"


def read_input(path: Path, limit: int = MAX_INPUT_BYTES, what: str = "", wanted: str = "") -> bytes:
    """The bytes of a requirement file; an :class:`InputError` naming the problem otherwise.

    Opened without blocking (a FIFO with no writer must not hang the run) and refused unless
    it is a regular file; at most ``limit`` bytes are read (``/dev/zero`` never ends).
    ``wanted``: what the file should have been, for a refusal (default: a requirement file,
    or a catalog file when ``what`` names one).
    """
    where = what + show(path, 200)
    wanted = wanted or f"a {what.strip() or 'requirement'} file (.toml)"
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_NOCTTY", 0)
    try:
        fd = os.open(path, flags | getattr(os, "O_CLOEXEC", 0))
    except FileNotFoundError:
        raise InputError(f"{where}: no such file") from None
    except IsADirectoryError:
        raise InputError(f"{where}: is a directory, expected {wanted}") from None
    except OSError as exc:
        raise InputError(f"{where}: cannot be read ({exc.strerror})") from None
    try:
        st = os.fstat(fd)
        if stat.S_ISDIR(st.st_mode):
            raise InputError(f"{where}: is a directory, expected {wanted}")
        if not stat.S_ISREG(st.st_mode):
            raise InputError(
                f"{where}: is {_kind_of(st.st_mode)}, not a regular file; give {wanted}"
            )
        too_big = InputError(
            f"{where}: larger than {limit // 1024} KiB"
            + ("" if what else "; a requirement file is a few kilobytes")
        )
        if st.st_size > limit:
            raise too_big
        chunks, total = [], 0
        while total <= limit:
            chunk = os.read(fd, min(65536, limit + 1 - total))
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
        if total > limit:
            raise too_big
        return b"".join(chunks)
    except OSError as exc:
        raise InputError(f"{where}: cannot be read ({exc.strerror})") from None
    finally:
        os.close(fd)


def depth(doc: Any) -> int:
    """How deep tables and arrays nest in ``doc`` (a scalar is 0), counted without
    recursion."""
    deepest, stack = 0, [(doc, 0)]
    while stack:
        node, d = stack.pop()
        if isinstance(node, dict):
            children = node.values()
        elif isinstance(node, list):
            children = node
        else:
            deepest = max(deepest, d)
            continue
        deepest = max(deepest, d + 1)
        if d + 1 > MAX_DEPTH:
            return d + 1
        stack.extend((c, d + 1) for c in children)
    return deepest


def parse_toml(raw: bytes, where: str) -> dict[str, Any]:
    """TOML bytes to a document: a BOM is accepted, deep nesting refused in one line."""
    try:
        text = raw.decode("utf-8").removeprefix("\ufeff")
    except UnicodeDecodeError:
        raise InputError(f"{where}: not a UTF-8 text file") from None
    nested = InputError(
        f"{where}: tables or arrays nested more than {MAX_DEPTH} levels deep; "
        "a requirement file or catalog needs three at most"
    )
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{where}: broken TOML: {clip(str(exc), 200)}") from None
    except RecursionError:
        raise nested from None
    if depth(data) > MAX_DEPTH:
        raise nested
    return data


def read_toml(path: Path, wanted: str = "") -> dict[str, Any]:
    """A requirement document read safely from ``path`` (see :func:`read_input`; ``wanted``
    as there: a report for ``advisor diff``)."""
    return parse_toml(read_input(path, wanted=wanted), show(path, 200))


# ------------------------------------------------------------------ writing
def same_file(a: Path, b: Path) -> bool:
    """Whether ``a`` and ``b`` are one file (through links); False if either is missing."""
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False


def check_target(path: Path) -> Path:
    """The file to write for ``path``: a symlink's final target; refused when it exists and
    is not a regular file (writing there would replace a device node or a FIFO)."""
    target = Path(os.path.realpath(path))
    try:
        st = os.stat(target)
    except FileNotFoundError:
        return target
    except OSError as exc:
        raise OutputError(f"{show(path, 200)}: cannot be written ({exc.strerror})") from None
    if not stat.S_ISREG(st.st_mode):
        raise OutputError(
            f"{show(path, 200)}: exists and is {_kind_of(st.st_mode)}; "
            "the report goes only to a regular file (a new one or one to replace)"
        )
    return target


def write_atomic(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` so that a reader sees the old file or the new one, never a
    half-written one: write a uniquely named temporary file beside the target, flush it to
    disk, then rename it over the target.

    A symlink is followed (its target is replaced, the link stays). A new file gets mode
    0666 less the umask, as an editor would create it; an existing file keeps its mode. On
    any failure the writer removes its own temporary file and nothing else.
    """
    target = check_target(Path(path))
    try:
        old_mode: int | None = stat.S_IMODE(os.stat(target).st_mode)
    except FileNotFoundError:
        old_mode = None
    directory = target.parent
    tmp = directory / f".{target.name[:100]}.{os.getpid()}-{os.urandom(6).hex()}.tmp"
    flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_CLOEXEC", 0)
    fd = os.open(tmp, flags, 0o666)  # the kernel applies the umask, as for an editor's file
    try:
        try:
            if old_mode is not None:
                os.fchmod(fd, old_mode)
            data = text.encode("utf-8")
            view = memoryview(data)
            while view:
                n = os.write(fd, view)
                view = view[n:]
            os.fsync(fd)
        finally:
            os.close(fd)
        os.replace(tmp, target)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise


#: The program name every message on stderr begins with.
PROG = "advisor"


def print_error(message: str) -> None:
    """Each line of ``message`` on stderr after the program name: controls escaped, at most
    :data:`LINE_CHARS` characters (a message never floods the terminal)."""
    room = LINE_CHARS - len(PROG) - 2  # "advisor: " comes first
    for line in message.splitlines() or [message]:
        text = printable(line)
        if len(text) > room:  # clip's "… (N characters)" counted in the room
            tail = f"… ({len(text):,} characters)"
            text = clip(text, room - len(tail) + 1)
        print(f"{PROG}: {text}", file=sys.stderr)


#: The longest line the command prints on stderr.
LINE_CHARS = 300
