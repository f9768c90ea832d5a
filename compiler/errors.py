"""The errors glint reports to a user: one clear message and an exit code, never a traceback.

Every error that can reach the command line derives from `GlintError`. The CLI catches it,
prints `glint: <message>` and exits with `exit_code`: 1 for a problem with the user's input
(a scene, a shader), 2 for usage or the environment (a missing tool, an unwritable path).
"""

from __future__ import annotations


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
