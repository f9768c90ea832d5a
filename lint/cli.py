"""`glint lint` and `glint rule`: registered on the `glint` command line through the
`glint.commands` entry point (see pyproject.toml).

Exit codes: 0 clean, 1 findings, 2 usage or internal error.
"""

from __future__ import annotations

import argparse
import gc
import json
import sys
from dataclasses import replace
from pathlib import Path

from glint.compiler.errors import EnvironmentProblem, UsageError, printable
from glint.compiler.files import is_temporary, write_atomic
from glint.compiler.glsl.includes import Expanded, IncludeError, expand_includes, has_includes
from glint.compiler.glsl.parser import prepare_parser
from glint.compiler.target.shadertoy import TARGETS, Tab, bind_channels, channel_binding

from .cache import LintCache, cache_directory
from .config import find_pyproject, load_options
from .docs import rules_markdown
from .finding import Finding
from .options import Options, enables_some_rule, unknown_code
from .parallel import lint_items
from .precision import precision_note
from .reporters import FORMATS, REPORTERS, statistics, summary
from .rules import all_rules, rule_doc
from .runner import LintResult, decode
from .tabs import plan, project_tabs, read_common, split_projects

EXTENSIONS = (".glsl", ".frag", ".fs")


def add_commands(sub: argparse._SubParsersAction) -> None:  # type: ignore[type-arg]
    lint = sub.add_parser(
        "lint",
        help="lint ShaderToy GLSL: glslang, portability, numerics, lighting, performance",
        description="Lint GLSL files (directories are searched for .glsl .frag .fs). "
        "Exit status: 0 clean, 1 findings, 2 usage or internal error.",
    )
    lint.add_argument("paths", nargs="+", metavar="PATH", help="files or directories; - is stdin")
    lint.add_argument("--format", choices=FORMATS, default="text", help="output format")
    lint.add_argument("--select", type=_code_list, help="codes or prefixes to enable, e.g. N,L001")
    lint.add_argument("--ignore", type=_code_list, help="codes or prefixes to disable")
    lint.add_argument("--fix", action="store_true", help="apply safe fixes in place")
    lint.add_argument(
        "--unsafe-fixes", action="store_true", help="with --fix, also apply unsafe fixes"
    )
    lint.add_argument(
        "--statistics", action="store_true", help="count findings per rule instead of listing"
    )
    lint.add_argument("--no-glslang", action="store_true", help="skip glslangValidator")
    lint.add_argument("--target", choices=TARGETS, help="how the file is wrapped (shadertoy)")
    add_tab_arguments(lint)
    lint.add_argument(
        "--no-cache",
        action="store_true",
        help="lint every file afresh; neither read nor write .glint_cache",
    )
    lint.add_argument(
        "--cache-dir",
        metavar="DIR",
        help="where the cache lives (default: .glint_cache beside pyproject.toml, else here; "
        "or $GLINT_CACHE_DIR)",
    )
    lint.add_argument(
        "-j",
        "--jobs",
        type=_jobs,
        default=0,
        metavar="N",
        help="worker processes (default 0: one per core; 1: lint in this process)",
    )
    lint.set_defaults(handler=cmd_lint)

    rule = sub.add_parser("rule", help="explain a lint rule, or list them all")
    rule.add_argument("code", nargs="?", help="rule code, e.g. N001")
    rule.add_argument("--all", action="store_true", help="every rule")
    rule.add_argument("--json", action="store_true", help="as JSON")
    rule.add_argument("--markdown", action="store_true", help="with --all: the reference page")
    rule.set_defaults(handler=cmd_rule)


def add_tab_arguments(parser: argparse.ArgumentParser) -> None:
    """--common and --channel: the ShaderToy tab the files are checked in (lint, validate)."""
    parser.add_argument(
        "--common",
        metavar="FILE",
        help="ShaderToy's Common tab, put in front of each file (default: NAME.common.glsl "
        "beside NAME.glsl when there is one)",
    )
    parser.add_argument(
        "--channel",
        action="append",
        type=channel_argument,
        metavar="N=KIND",
        help="what iChannelN is bound to: 2d (the default), cube or 3d; e.g. --channel 0=cube",
    )


def channel_argument(text: str) -> tuple[int, str]:
    try:
        return channel_binding(text)
    except ValueError as exc:
        raise argparse.ArgumentTypeError(str(exc)) from None


def _jobs(text: str) -> int:
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of processes, got {text!r}") from None
    if value < 0:
        raise argparse.ArgumentTypeError("must be 0 (one per core) or more")
    return value


def _code_list(text: str) -> list[str]:
    return [c.strip().upper() for c in text.split(",") if c.strip()]


def _check_codes(codes: list[str], flag: str) -> None:
    if not codes:
        raise UsageError(f"{flag}: no rule code given; e.g. {flag} N001,L (ALL: every rule)")
    unknown = unknown_code(codes)
    if unknown is not None:
        raise UsageError(f"{flag}: unknown rule code or prefix {unknown!r}; see `glint rule --all`")


def options_for(args: argparse.Namespace) -> Options:
    """The configuration file's options (checked as it is read), then the flags; a selection
    that leaves no rule to run is a usage error rather than a silent "All clean"."""
    options, path = load_options()
    if args.select is not None:
        _check_codes(args.select, "--select")
        options.select = args.select
    if args.ignore is not None:
        if args.ignore:
            _check_codes(args.ignore, "--ignore")
        options.ignore = args.ignore
    if args.target is not None:
        options.target = args.target
    options.glslang = not args.no_glslang
    if getattr(args, "channel", None):
        options.channels = bind_channels(options.channels, args.channel)
    if not enables_some_rule(options):
        default = Options()

        def origin(flag: str, given: list[str] | None, codes: list[str], usual: list[str]) -> str:
            where = flag if given is not None else "the default" if codes == usual else path
            return f"{','.join(codes) or 'nothing'} ({where})"

        raise UsageError(
            "no rule is left to run: select "
            + origin("--select", args.select, options.select, default.select)
            + ", ignore "
            + origin("--ignore", args.ignore, options.ignore, default.ignore)
            + "; select a rule that is not ignored, e.g. --select DEFAULT"
        )
    return options


def _lintable(path: Path) -> bool:
    """A shader file found in a folder; not a temporary file of glint's own writer (a killed
    run can leave one behind)."""
    return path.suffix in EXTENSIONS and not is_temporary(path.name) and path.is_file()


def collect(paths: list[str]) -> list[str]:
    """The files to lint: files as given, directories searched for shader extensions."""
    files: list[str] = []
    for raw in paths:
        if raw == "-":
            files.append(raw)
            continue
        path = Path(raw)
        if path.is_dir():
            found = sorted(p for p in path.rglob("*") if _lintable(p))
            files += [str(p) for p in found]
        elif path.is_file():
            files.append(raw)
        elif path.exists():  # a device or a FIFO: endless, or blocks until someone writes
            raise UsageError(
                f"{printable(raw)}: not a regular file (a device, a FIFO or a socket); name a "
                "shader file, or pipe it in with -"
            )
        else:
            raise UsageError(f"{printable(raw)}: no such file or directory")
    return files


def read_source(file: str) -> bytes:
    """The bytes of a file to lint (`-`: standard input)."""
    if file == "-":
        return sys.stdin.buffer.read()
    try:
        return Path(file).read_bytes()
    except OSError as exc:
        raise EnvironmentProblem(f"{printable(file)}: cannot read: {exc.strerror}") from None


def cmd_lint(args: argparse.Namespace) -> int:
    if args.unsafe_fixes and not args.fix:
        raise UsageError("--unsafe-fixes needs --fix")
    options = options_for(args)
    common = read_common(args.common) if args.common is not None else None
    paths, projects = split_projects(args.paths)
    if projects and args.fix:
        raise UsageError(
            f"{printable(projects[0].origin)}: --fix rewrites files, and a project's passes "
            "live in its JSON or its tabs: fix the tab files, or lint without --fix"
        )
    planned = plan(collect(paths), common, options) if paths else []
    texts: dict[str, bytes] = {}
    for project in projects:
        for name, tab, text in project_tabs(project, options):
            planned.append((name, tab))
            texts[name] = text.encode("utf-8")
    expanded, unfollowed = _expand_includes([file for file, _ in planned], texts, args.fix)
    files = [file for file, _ in planned]
    results = _lint_files(files, [tab for _, tab in planned], options, args, texts)
    results = [
        _with_include_error(_mapped_back(result, expanded.get(file)), unfollowed.get(file))
        for file, result in zip(files, results, strict=True)
    ]
    findings: list[Finding] = []
    sources: dict[str, str] = {}
    fixed = 0
    for file, result in zip(files, results, strict=True):
        findings += result.findings
        sources[result.file] = result.text
        if file in expanded:  # the included files' own text, for the findings there
            sources.update(expanded[file].sources)
        for note in result.notes:
            print(f"glint: {printable(note)}", file=sys.stderr)
        if result.fixed:
            fixed += result.fixed
            if file == "-":
                sys.stdout.flush()
                sys.stdout.buffer.write(result.encoded())
                sys.stdout.buffer.flush()
            else:
                write_atomic(file, result.encoded())  # whole, in place of what it fixes
    out = sys.stdout if "-" not in files or not args.fix else sys.stderr
    if args.statistics:
        out.write(statistics(findings))
    else:
        out.write(REPORTERS[args.format](findings, sources))
    if args.format in ("text", "concise") or args.statistics:
        out.write(summary(findings, fixed))
    if any(result.failed for result in results):
        return 2  # glint failed on a file (its note says which): the report is not whole
    return 1 if findings else 0


def _expand_includes(
    files: list[str], texts: dict[str, bytes], fix: bool
) -> tuple[dict[str, Expanded], dict[str, IncludeError]]:
    """Every file's bytes into `texts`, those of the files that `#include` others expanded: a
    file is linted with what it includes, as a compiler sees it. --fix cannot write an
    expansion back. An include that cannot be followed (a missing file, a cycle) is that
    file's finding: the file is linted as it stands and the others go on."""
    expanded: dict[str, Expanded] = {}
    unfollowed: dict[str, IncludeError] = {}
    for file in files:
        if file == "-" or file in texts:
            continue
        data = read_source(file)
        texts[file] = data  # read once: linting takes it from here
        if b"include" not in data:  # most files: no decoding for this
            continue
        text, problem = decode(data, file)
        if problem or not has_includes(text):
            continue
        if fix:
            raise UsageError(
                f"{printable(file)}: --fix rewrites a file, and this one includes others: lint "
                "it without --fix, or fix the included files on their own"
            )
        try:
            expanded[file] = expand_includes(text, file)
        except IncludeError as problem:
            unfollowed[file] = problem
            continue
        texts[file] = expanded[file].text.encode("utf-8", "surrogateescape")
    return expanded, unfollowed


def _with_include_error(result: LintResult, problem: IncludeError | None) -> LintResult:
    """A file whose include could not be followed: that problem as its finding, in place of
    the preprocessor's word that it does not know #include."""
    if problem is None:
        return result
    finding = Finding(problem.file, problem.line, 1, problem.line, 1, "C004", "error",
                      problem.reason)  # fmt: skip
    kept = [f for f in result.findings if not (f.code == "C004" and "#include" in f.message)]
    return replace(result, findings=[finding, *kept])


def _mapped_back(result: LintResult, expanded: Expanded | None) -> LintResult:
    """A result on an expanded file with each finding at the file and line it came from."""
    if expanded is None:
        return result

    def moved(finding: Finding) -> Finding:
        file, line = expanded.origin(finding.line)
        end_file, end_line = expanded.origin(finding.end_line)
        end = end_line if end_file == file else line
        return replace(finding, file=file, line=line, end_line=max(end, line), fix=None)

    # the file's own text (what its findings' lines count in), not the expansion
    own = expanded.sources.get(result.file, result.text)
    return replace(result, findings=[moved(f) for f in result.findings], text=own)


def _lint_files(
    files: list[str],
    tabs: list[Tab],
    options: Options,
    args: argparse.Namespace,
    texts: dict[str, bytes] | None = None,
) -> list[LintResult]:
    """Each file's result, in order: from the cache when its bytes, name, tab and the settings
    are unchanged, the others linted (in parallel when there are enough of them). Fixing never
    reads the cache: it lints afresh, and stores the findings of what it leaves on disk.
    `texts`: the code of a project's passes, by the name they are reported under."""
    texts = texts or {}
    names = ["<stdin>" if file == "-" else file for file in files]
    data = [texts[file] if file in texts else read_source(file) for file in files]
    cache = None
    if not args.no_cache:
        where = cache_directory(args.cache_dir, find_pyproject(Path.cwd().resolve()))
        cache = LintCache(where, options)
    results: list[LintResult | None] = [None] * len(files)
    if cache is not None and not args.fix:
        for index, (name, content) in enumerate(zip(names, data, strict=True)):
            found = cache.load(name, content, tabs[index])
            if found is not None:
                results[index] = LintResult(name, found, decode(content, name)[0])
    todo = [index for index, result in enumerate(results) if result is None]
    items = [(names[index], data[index]) for index in todo]
    # What is alive now (modules, rules, parser tables) lives as long as this command: the
    # cycle collector need not scan it again and again while files are linted. It spent a
    # fifth of a cold run's CPU doing so; forked workers inherit the frozen objects too.
    if items:
        prepare_parser()
    gc.freeze()
    fresh = lint_items(
        items, options, args.fix, args.unsafe_fixes, args.jobs, [tabs[i] for i in todo]
    )
    for index, result in zip(todo, fresh, strict=True):
        results[index] = result
        if cache is not None and not result.failed and not (result.fixed and files[index] == "-"):
            # the bytes the file holds after this run (a fixed file: UTF-8, its BOM kept)
            now = result.encoded() if result.fixed else data[index]
            cache.store(names[index], now, result.findings, tabs[index])
    return [result for result in results if result is not None]


def cmd_rule(args: argparse.Namespace) -> int:
    rules = all_rules()
    if args.all == (args.code is not None):
        raise UsageError("give a rule code (glint rule N001) or --all")
    if args.code is not None:
        code = args.code.upper()
        if code not in rules:
            raise UsageError(f"unknown rule {args.code!r}; see `glint rule --all`")
        chosen = [code]
    else:
        chosen = list(rules)
    entries = [rule_entry(code) for code in chosen]
    if args.markdown:
        if not args.all:
            raise UsageError("--markdown goes with --all")
        sys.stdout.write(rules_markdown())
        return 0
    if args.json:
        sys.stdout.write(json.dumps(entries if args.all else entries[0], indent=2) + "\n")
        return 0
    for entry in entries:
        if args.all:
            print(f"{entry['code']:<6} {entry['name']:<34} {entry['category']:<12} "
                  f"{entry['summary']}")  # fmt: skip
        else:
            print(explain(entry))
    return 0


def rule_entry(code: str) -> dict[str, str]:
    rule = all_rules()[code]
    doc = rule_doc(rule)
    return {
        "code": code,
        "name": rule.name,
        "category": rule.category,
        "severity": rule.severity,
        "certainty": rule.certainty,
        "fixable": rule.fixable,
        "runs": "default" if rule.default else "opt-in",
        **doc,
        "on_real_shaders": precision_note(code),
    }


def explain(entry: dict[str, str]) -> str:
    fix = {"safe": "a safe fix (--fix)", "unsafe": "an unsafe fix (--fix --unsafe-fixes)"}
    head = (
        f"{entry['code']} {entry['name']} ({entry['category']}, {entry['severity']}"
        + (f", {fix[entry['fixable']]}" if entry["fixable"] in fix else "")
        + ")"
    )
    parts = [head, "", entry["summary"]] + (["", entry["details"]] if entry["details"] else [])
    sections = (("Why is this bad?", "why"), ("Example:", "example"),
                (f"{entry['fix_title']}:", "fix"), ("Fix safety:", "fix_safety"),
                ("References:", "references"), ("On real shaders:", "on_real_shaders"))  # fmt: skip
    for title, key in sections:
        if entry[key]:
            body = "\n".join("    " + line if line else "" for line in entry[key].split("\n"))
            parts += ["", title, body]
    return "\n".join(parts)
