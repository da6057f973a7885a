#!/usr/bin/env python3
"""clang-tidy over translation units, each result reused while nothing it reads has changed.

Called by scripts/lint.sh. A unit's result is keyed by a SHA-256 of everything clang-tidy's
answer depends on: the unit preprocessed by clang (every header it includes, the system's too,
so a package update or an edited header invalidates exactly the units that include it), its
compile command, every .clang-tidy of the repository, and clang-tidy's version. The source and
build folders are written as placeholders in both the key and the stored output, so another
clone of the same commit (CI's, on this machine) reuses the results of this one. A result is
stored only when clang-tidy ran to the end (exit 0); the warnings it found are stored with it,
so a cached unit reports them again, as a fresh run would.

The cache lives outside the clone: $EMIT_LINT_CACHE, else $XDG_CACHE_HOME/emit/clang-tidy, else
~/.cache/emit/clang-tidy; entries not used for 30 days are removed. --no-cache runs every unit.

Usage: clang_tidy_cached.py --clang-tidy PATH --build DIR --root DIR --logs DIR --jobs N
                            [--no-cache] UNIT...
Writes each unit's output to LOGS/<unit path with / as _>.log and prints one line:
"<units> units, <hits> from the cache".
"""
import argparse
import concurrent.futures
import hashlib
import json
import os
import pathlib
import shlex
import subprocess
import sys
import time

ROOT_MARK = "@EMIT_SOURCE@"
BUILD_MARK = "@EMIT_BUILD@"
MAX_AGE_S = 30 * 24 * 3600


def cache_folder():
    if os.environ.get("EMIT_LINT_CACHE"):
        return pathlib.Path(os.environ["EMIT_LINT_CACHE"])
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return pathlib.Path(base) / "emit" / "clang-tidy"


def normalise(text, root, build):
    # The build folder first: it may lie inside the source folder.
    return text.replace(build, BUILD_MARK).replace(root, ROOT_MARK)


def compile_arguments(entry):
    """The compile command's arguments, without the output (-o FILE) and the compile-only flag."""
    args = entry["arguments"] if "arguments" in entry else shlex.split(entry["command"])
    kept, skip = [], False
    for arg in args[1:]:
        if skip:
            skip = False
            continue
        if arg == "-o":
            skip = True
            continue
        if arg == "-c" or arg.startswith("-o"):
            continue
        kept.append(arg)
    return kept


def key_of(unit, entry, clang, common, root, build):
    """The unit's key, or None when clang cannot preprocess it (clang-tidy then runs, and says why)."""
    args = compile_arguments(entry)
    run = subprocess.run([clang, "-E", *args], cwd=entry["directory"], capture_output=True)
    if run.returncode != 0:
        return None
    digest = hashlib.sha256(common)
    digest.update(normalise(" ".join(args), root, build).encode())
    digest.update(b"\0")
    digest.update(normalise(run.stdout.decode("utf-8", "surrogateescape"), root, build).encode("utf-8", "surrogateescape"))
    return digest.hexdigest()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--clang-tidy", required=True)
    parser.add_argument("--clang", required=True, help="clang++ of clang-tidy's version, to preprocess")
    parser.add_argument("--build", required=True)
    parser.add_argument("--root", required=True)
    parser.add_argument("--logs", required=True)
    parser.add_argument("--jobs", type=int, default=os.cpu_count())
    parser.add_argument("--no-cache", action="store_true")
    parser.add_argument("units", nargs="+")
    options = parser.parse_args()
    root = os.path.realpath(options.root)
    build = os.path.realpath(options.build)
    database = {os.path.normpath(os.path.join(e["directory"], e["file"])): e
                for e in json.load(open(os.path.join(build, "compile_commands.json")))}

    version = subprocess.run([options.clang_tidy, "--version"], capture_output=True, check=True).stdout
    configs = subprocess.run(["git", "-C", root, "ls-files", "--", ".clang-tidy", "*/.clang-tidy"],
                             capture_output=True, check=True, text=True).stdout.split()
    common = hashlib.sha256(version)
    for config in sorted(configs):
        common.update(config.encode() + b"\0" + (pathlib.Path(root) / config).read_bytes())
    common = common.hexdigest().encode()

    cache = None if options.no_cache else cache_folder()
    if cache:
        cache.mkdir(parents=True, exist_ok=True)
        now = time.time()
        for old in cache.glob("*.log"):
            if now - old.stat().st_mtime > MAX_AGE_S:
                old.unlink(missing_ok=True)

    def lint(unit):
        log = pathlib.Path(options.logs) / (os.path.relpath(unit, root).replace("/", "_") + ".log")
        entry = database[unit]
        key = key_of(unit, entry, options.clang, common, root, build) if cache else None
        stored = cache / (key + ".log") if key else None
        if stored and stored.exists():
            text = stored.read_text(encoding="utf-8", errors="surrogateescape")
            log.write_text(text.replace(BUILD_MARK, build).replace(ROOT_MARK, root),
                           encoding="utf-8", errors="surrogateescape")
            os.utime(stored)
            return True
        run = subprocess.run([options.clang_tidy, "-p", build, "--quiet", unit], capture_output=True)
        text = (run.stdout + run.stderr).decode("utf-8", "surrogateescape")
        if run.returncode != 0:
            text += f"clang-tidy exited {run.returncode} on {unit}\n"
        log.write_text(text, encoding="utf-8", errors="surrogateescape")
        if stored and run.returncode == 0:
            partial = stored.with_suffix(f".{os.getpid()}.partial")
            partial.write_text(normalise(text, root, build), encoding="utf-8", errors="surrogateescape")
            partial.replace(stored)
        return False

    missing = [u for u in options.units if u not in database]
    if missing:
        print(f"clang_tidy_cached: not in {build}/compile_commands.json: {missing[0]}", file=sys.stderr)
        return 2
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, options.jobs)) as pool:
        hits = sum(pool.map(lint, options.units))
    print(f"{len(options.units)} units, {hits} from the cache")
    return 0


if __name__ == "__main__":
    sys.exit(main())
