"""The CLI reference page, rendered from the `glint` argument parser itself.

The parser (`glint.compiler.cli.build_parser`, with the commands other packages register
through the `glint.commands` entry point) is the one truth about the options, so the page is
its help text, command by command, never a copy that could drift.
"""

from __future__ import annotations

import argparse
from collections.abc import Iterator
from pathlib import PurePosixPath

from glint.compiler.cli import build_parser
from glint.compiler.markdown import fenced, md_code

CLI_PAGE = PurePosixPath("cli.md")
HELP_WIDTH = 100  # fixed, so that the page does not depend on the terminal that built it


def cli_pages() -> dict[PurePosixPath, str]:
    return {CLI_PAGE: cli_page(build_parser())}


def cli_page(parser: argparse.ArgumentParser) -> str:
    """The help of `parser` and of every subcommand under it, each under its own heading."""
    parts = [
        "# Command line\n\n",
        f"Generated from the argument parser of {md_code(parser.prog)}: each command's "
        f"{md_code('--help')}.\n\n",
        fenced(_help(parser), "text"),
    ]
    for name, command in commands(parser):
        parts += [f"\n## {md_code(name)}\n\n", fenced(_help(command), "text")]
    return "".join(parts)


def commands(parser: argparse.ArgumentParser) -> Iterator[tuple[str, argparse.ArgumentParser]]:
    """(full command name, parser) of every subcommand, depth first (`glint catalog show`).
    argparse keeps subcommands only in its private `_actions`; there is no public way."""
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for sub in dict.fromkeys(action.choices.values()):  # aliases share one parser
                yield sub.prog, sub
                yield from commands(sub)


def _help(parser: argparse.ArgumentParser) -> str:
    def formatter(prog: str) -> argparse.HelpFormatter:
        return argparse.HelpFormatter(prog, width=HELP_WIDTH)

    original = parser.formatter_class
    parser.formatter_class = formatter  # type: ignore[assignment]
    try:
        return parser.format_help()
    finally:
        parser.formatter_class = original
