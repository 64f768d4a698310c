#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Mutant campaign: thousands of mutated suite scenes through the real CLI (docs/contributing/testing.md, "Fuzzing").

One command, fixed seed, the same mutants on every machine:

    python3 scripts/fuzz_campaign.py                     # 5000 mutants, seed 18, 2 at a time
    python3 scripts/fuzz_campaign.py --count 200 --build build-sanitize
    python3 scripts/fuzz_campaign.py --target moordyn    # MoorDyn decks: catena import moordyn
    python3 scripts/fuzz_campaign.py --target check      # results files: catena check R --scene S
    python3 scripts/fuzz_campaign.py --target report     # results JSON: catena report --from R

--target scene (the default) mutates the suite's scenes. The other targets (issue 32) mutate the seed
files of tests/fuzz/corpus/TARGET with the same mutator (`catena_input_fuzz --emit`; the report
target's seeds are results documents Catena writes itself) and run
`catena import moordyn MUTANT --out DIR`, `catena check MUTANT --scene tests/fuzz/corpus/check/scene.toml`
or `catena report --from MUTANT --out DIR --no-figures`; they have no result JSON to inspect, so
their classes are the exit status, signals, sanitizer reports and timeouts.

The mutants are made by the fuzzer's own mutator (`catena_scene_fuzz --emit`, tests/fuzz/), so
the campaign and the in-process fuzz test share one definition of a mutation. Each mutant runs as
`catena solve MUTANT --json OUT --quiet` with a timeout, and is classified:

    ok          exit 0, 1 or 2 (solved, a check failed, bad input named) with a clean result
    signal      killed by a signal (segmentation fault, abort, ...)
    sanitizer   an AddressSanitizer / UBSan report (sanitizer builds)
    exit-3      internal error or a scene left unsolved by a numerical failure
    exit-other  any other exit status
    timeout     still running after --timeout seconds
    nan         NaN or Infinity in the JSON, or "nan" printed as a number in a message (when the
                input itself has no "nan" for the message to repeat)
    bad-output  a JSON file left behind that is empty or does not parse
    bad-converged  a result reported as converged with a null, non-finite or non-positive
                frequency, or a null forced response without a diagnostic

Writes OUT/summary.md (a table by class with one example each), OUT/failures.tsv (every failing
mutant: class, file, seed scene, recipe, detail) and copies the failing mutants to
OUT/regression-seeds/<class>/. Prints the totals in one line; exits 1 when anything failed.
"""

import argparse
import collections
import concurrent.futures
import json
import math
import os
import re
import shutil
import subprocess
import sys
import time

FAILURE_CLASSES = ["signal", "sanitizer", "exit-3", "exit-other", "timeout", "nan", "bad-output",
                   "bad-converged"]
# "nan" or "-nan" printed as a number in a message (not inside a word such as "nanosecond").
# "inf" is not looked for: "EA = inf" is how an inextensible cable is written.
NAN_TEXT = re.compile(r"(?<![A-Za-z_])[-+]?nan(?![A-Za-z_])", re.IGNORECASE)


def parse_arguments():
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=5000, help="number of mutants (default 5000)")
    parser.add_argument("--seed", type=int, default=18, help="campaign seed (default 18)")
    parser.add_argument("--jobs", type=int, default=2, help="mutants run at a time (default 2)")
    parser.add_argument("--timeout", type=float, default=30.0, help="seconds per mutant (default 30)")
    parser.add_argument("--time-limit", type=float, default=None,
                        help="pass `--time-limit SECONDS` to catena solve (its own budget: a long but legal "
                             "request then ends with a partial result instead of a timeout); default none")
    parser.add_argument("--build", default=os.path.join(root, "build"), help="build directory")
    parser.add_argument("--scenes", default=os.path.join(root, "verification", "scenes"),
                        help="seed corpus (default verification/scenes)")
    parser.add_argument("--out", default=None, help="output directory (default BUILD/fuzz-campaign)")
    parser.add_argument("--no-build", action="store_true", help="do not build catena and the fuzzer first")
    parser.add_argument("--target", default="scene", choices=["scene", "moordyn", "check", "report"],
                        help="what is mutated and which command reads it (default scene)")
    return parser.parse_args()


def build_tools(arguments):
    fuzzer_name = "catena_scene_fuzz" if arguments.target == "scene" else "catena_input_fuzz"
    if not arguments.no_build:
        subprocess.run(["cmake", "--build", arguments.build, "-j", str(arguments.jobs), "--target",
                        "catena_cli", fuzzer_name], check=True, stdout=subprocess.DEVNULL)
    cli = os.path.join(arguments.build, "catena")
    fuzzer = os.path.join(arguments.build, "tests", fuzzer_name)
    for path in (cli, fuzzer):
        if not os.access(path, os.X_OK):
            sys.exit(f"fuzz_campaign: {path} not found (configure {arguments.build} with tests on)")
    return cli, fuzzer


def emit_mutants(fuzzer, arguments, mutants_dir):
    shutil.rmtree(mutants_dir, ignore_errors=True)
    command = [fuzzer, "--corpus", arguments.scenes, "--emit", mutants_dir, "--iterations",
               str(arguments.count), "--seed", str(arguments.seed)]
    if arguments.target != "scene":
        command = [fuzzer, "--target", arguments.target, "--corpus", corpus_dir(arguments.target)] + command[3:]
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    recipes = []
    with open(os.path.join(mutants_dir, "recipes.tsv"), encoding="utf-8", errors="replace") as table:
        for line in table:
            name, seed_scene, recipe = line.rstrip("\n").split("\t", 2)
            recipes.append((name, os.path.basename(seed_scene), recipe))
    return recipes


def corpus_dir(target):
    root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
    return os.path.join(root, "tests", "fuzz", "corpus", target)


def input_command(cli, target, mutant, scratch):
    """The CLI command that reads a mutant of another program's file (--target moordyn/check/report)."""
    if target == "moordyn":
        return [cli, "import", "moordyn", mutant, "--out", scratch]
    if target == "check":
        return [cli, "check", mutant, "--scene", os.path.join(corpus_dir("check"), "scene.toml")]
    return [cli, "report", "--from", mutant, "--out", scratch, "--no-figures"]


def reject_constant(token):
    raise ValueError(f"{token} in JSON")


def converged(summary):
    return isinstance(summary, dict) and summary.get("termination") == "converged"


def bad_converged_in(scene):
    """The first converged result with a null, non-finite or non-positive value, or None."""
    for solver, output in (scene.get("solvers") or {}).items():
        for plane in ("inplane", "outofplane"):
            result = output.get(plane)
            if not result or not (converged(result.get("summary")) or converged(output.get("summary"))):
                continue
            for mode in result.get("modes", []):
                omega = mode.get("omega_rad_s")
                if not isinstance(omega, (int, float)) or not math.isfinite(omega) or omega <= 0:
                    return f"{solver} {plane} mode {mode.get('index')}: omega {omega} reported as converged"
        if not converged(output.get("summary")):
            continue
        for response in output.get("forced", []):
            if response.get("max_abs_tension_n") is None and not response.get("diagnostic"):
                return f"{solver} forced at {response.get('omega_rad_s')} rad/s: null response, no diagnostic"
    return None


# Keys whose text Catena writes itself (names, descriptions and sources echo the scene's own
# strings, which a mutant may have set to "nan").
GENERATED_TEXT_KEYS = {"message", "brief", "warnings", "notes", "detail", "error", "diagnostic"}


def generated_strings(value, key=None):
    if isinstance(value, str):
        if key in GENERATED_TEXT_KEYS:
            yield value
    elif isinstance(value, dict):
        for item_key, item in value.items():
            yield from generated_strings(item, item_key)
    elif isinstance(value, list):
        for item in value:
            yield from generated_strings(item, key)


def check_json(path, input_has_nan):
    """(class, detail) for a JSON result that is not clean, else None. A message may repeat a "nan"
    the input itself contains (naming the bad value): only a NaN the input did not have counts."""
    if not os.path.exists(path):
        return None
    with open(path, "rb") as handle:
        raw = handle.read()
    if not raw:
        return "bad-output", "0-byte JSON left behind"
    try:
        document = json.loads(raw.decode("utf-8"), parse_constant=reject_constant)
    except ValueError as error:
        kind = "nan" if "in JSON" in str(error) else "bad-output"
        return kind, f"JSON: {error}"[:200]
    for text in generated_strings(document):
        if NAN_TEXT.search(text) and not input_has_nan:
            return "nan", f"message: {text}"[:200]
    for scene in document.get("scenes", []):
        detail = bad_converged_in(scene)
        if detail:
            return "bad-converged", detail
    return None


def run_mutant(cli, arguments, mutants_dir, json_dir, name):
    mutant = os.path.join(mutants_dir, name)
    result_path = os.path.join(json_dir, name.replace(".toml", ".json"))
    scratch = os.path.join(json_dir, name + ".out")
    started = time.monotonic()
    try:
        command = [cli, "solve", mutant, "--json", result_path, "--quiet"]
        if arguments.target != "scene":
            command = input_command(cli, arguments.target, mutant, scratch)
        if arguments.time_limit and arguments.target == "scene":
            command += ["--time-limit", f"{arguments.time_limit:g}"]
        run = subprocess.run(command, capture_output=True, timeout=arguments.timeout)
    except subprocess.TimeoutExpired:
        return name, "timeout", f"still running after {arguments.timeout:g} s", time.monotonic() - started
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    elapsed = time.monotonic() - started
    stderr = run.stderr.decode("utf-8", errors="replace")
    first_line = (stderr.strip().splitlines() or [""])[-1][:200]
    if "Sanitizer" in stderr or "runtime error:" in stderr:
        return name, "sanitizer", first_line, elapsed
    if run.returncode < 0:
        return name, "signal", f"signal {-run.returncode}", elapsed
    if run.returncode == 3:
        return name, "exit-3", first_line, elapsed
    if run.returncode not in (0, 1, 2):
        return name, "exit-other", f"exit {run.returncode}: {first_line}", elapsed
    if arguments.target != "scene":
        return name, f"exit-{run.returncode}", "", elapsed
    with open(mutant, "rb") as handle:
        input_has_nan = NAN_TEXT.search(handle.read().decode("utf-8", errors="replace")) is not None
    finding = check_json(result_path, input_has_nan)
    # toml11's hints list the valid float literals ("inf, nan"): not a value we printed.
    nan_lines = [line for line in stderr.splitlines() if NAN_TEXT.search(line) and not line.startswith("Hint:")]
    if finding is None and nan_lines and not input_has_nan:
        finding = ("nan", f"stderr: {nan_lines[0][:200]}")
    if finding:
        return name, finding[0], finding[1], elapsed
    return name, f"exit-{run.returncode}", "", elapsed


def run_all(cli, arguments, mutants_dir, json_dir, recipes):
    os.makedirs(json_dir, exist_ok=True)
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=arguments.jobs) as pool:
        futures = [pool.submit(run_mutant, cli, arguments, mutants_dir, json_dir, name) for name, _, _ in recipes]
        for done, future in enumerate(concurrent.futures.as_completed(futures), 1):
            name, kind, detail, elapsed = future.result()
            results[name] = (kind, detail, elapsed)
            if done % 250 == 0:
                print(f"  {done}/{len(recipes)} mutants", file=sys.stderr, flush=True)
    return results


def write_reports(arguments, out_dir, mutants_dir, recipes, results, wall_s):
    counts = collections.Counter(kind for kind, _, _ in results.values())
    examples = {}
    seeds_dir = os.path.join(out_dir, "regression-seeds")
    shutil.rmtree(seeds_dir, ignore_errors=True)
    with open(os.path.join(out_dir, "failures.tsv"), "w", encoding="utf-8") as failures:
        failures.write("class\tmutant\tseed scene\trecipe\tdetail\n")
        for name, seed_scene, recipe in recipes:
            kind, detail, _ = results[name]
            if kind not in FAILURE_CLASSES:
                continue
            failures.write(f"{kind}\t{name}\t{seed_scene}\t{recipe}\t{detail}\n")
            examples.setdefault(kind, (name, seed_scene, recipe, detail))
            os.makedirs(os.path.join(seeds_dir, kind), exist_ok=True)
            shutil.copy(os.path.join(mutants_dir, name), os.path.join(seeds_dir, kind, name))
    slowest = max(results.items(), key=lambda item: item[1][2])
    with open(os.path.join(out_dir, "summary.md"), "w", encoding="utf-8") as summary:
        summary.write(f"# Fuzz campaign ({arguments.target}): {len(recipes)} mutants, seed {arguments.seed}, "
                      f"timeout {arguments.timeout:g} s, {arguments.jobs} at a time, {wall_s:.0f} s\n\n")
        summary.write("| class | count | example (mutant, seed scene, recipe, detail) |\n|---|---:|---|\n")
        for kind in FAILURE_CLASSES + ["exit-0", "exit-1", "exit-2"]:
            example = examples.get(kind)
            text = " ; ".join(example).replace("|", "\\|") if example else ""
            summary.write(f"| {kind} | {counts.get(kind, 0)} | {text} |\n")
        summary.write(f"\nSlowest mutant: {slowest[0]} ({slowest[1][2]:.1f} s).\n")
    return counts


def main():
    arguments = parse_arguments()
    out_dir = arguments.out or os.path.join(
        arguments.build, "fuzz-campaign" + ("" if arguments.target == "scene" else "-" + arguments.target))
    mutants_dir = os.path.join(out_dir, "mutants")
    cli, fuzzer = build_tools(arguments)
    started = time.monotonic()
    recipes = emit_mutants(fuzzer, arguments, mutants_dir)
    json_dir = os.path.join(out_dir, "json")
    shutil.rmtree(json_dir, ignore_errors=True)
    results = run_all(cli, arguments, mutants_dir, json_dir, recipes)
    wall_s = time.monotonic() - started
    counts = write_reports(arguments, out_dir, mutants_dir, recipes, results, wall_s)
    failed = sum(counts.get(kind, 0) for kind in FAILURE_CLASSES)
    print(f"fuzz campaign ({arguments.target}): {len(recipes)} mutants (seed {arguments.seed}): "
          + ", ".join(f"{counts.get(kind, 0)} {kind}" for kind in FAILURE_CLASSES)
          + f"; ok: {counts.get('exit-0', 0)} exit 0, {counts.get('exit-1', 0)} exit 1, "
          f"{counts.get('exit-2', 0)} exit 2; {failed} failing; {wall_s:.0f} s; see {out_dir}/summary.md")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
