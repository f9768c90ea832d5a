"""The errors glint reports to a user: one clear message and an exit code, never a traceback.

Every error that can reach the command line derives from `GlintError`. The CLI catches it,
prints `glint: <message>` and exits with `exit_code`: 1 for a problem with the user's input
(a scene, a shader), 2 for usage or the environment (a missing tool, an unwritable path).
"""

from __future__ import annotations

import re

# Characters a terminal acts on or that break a line: C0 and C1 controls, DEL, the line and
# paragraph separators, and the bidirectional overrides that reorder what is shown. A file name
# or a value quoted in a message must not drive the terminal or forge a line.
TERMINAL_CONTROLS = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def printable(text: str, keep_line_feeds: bool = False) -> str:
    """Text for a terminal: each control character as its Python escape (`\\n`, `\\x1b`); with
    `keep_line_feeds`, a line feed stays (a message that lists one problem per line)."""

    def escape(match: re.Match[str]) -> str:
        char = match.group()
        return char if keep_line_feeds and char == "\n" else repr(char)[1:-1]

    return TERMINAL_CONTROLS.sub(escape, text)


class GlintError(Exception):
    """Base of every error glint reports; `message` says what is wrong and what to do."""

    exit_code = 1

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


class InputError(GlintError):
    """The user's input (a scene, a shader, a snippet) is wrong; exit code 1."""

    exit_code = 1


class EnvironmentProblem(GlintError):
    """A tool or library glint needs is missing or unusable, or a path cannot be written; exit 2."""

    exit_code = 2


class UsageError(GlintError):
    """The command line itself is wrong; exit code 2."""

    exit_code = 2
