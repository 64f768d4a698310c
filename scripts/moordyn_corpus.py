#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Published MoorDyn decks imported and solved with defaults (docs/how-to/moordyn-import.md,
"Decks tried").

For each deck of the list (`owner/name:path` rows): the deck is read from a local git mirror of its
repository (`git show HEAD:path`; no network, nothing copied into this repository), imported with
`catena import moordyn` into a temporary directory (exit code, rows converted or refused with their
reasons), and each scene it writes is solved twice:

1. `catena solve SCENE --json` with the defaults (exit code and wall time);
2. shooting alone at rtol 1e-13 (the scene with `[solvers] shooting = { rtol = 1e-13 }`), the
   reference for fe: per mode, fe's relative difference from it and the ratio of that difference to
   fe's own estimate (actual / estimate; an honest estimate keeps it below 1).

Writes DIR/corpus.md (a markdown table per deck and per scene, and the fe-vs-shooting summary)
and DIR/corpus.json (every number). Usage:

    scripts/moordyn_corpus.py --catena build/catena --out /tmp/corpus [-j 2] [--time-limit 120]

Mirrors: DIR/<owner>+<name>/repo (a git directory) under each --mirror (default /work/.mirror).
"""
import argparse
import concurrent.futures
import datetime
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

REPO_ROOT = Path(__file__).resolve().parent.parent
DEFAULT_DECKS = REPO_ROOT / "verification" / "corpus" / "moordyn-decks.txt"
REFERENCE_RTOL = 1e-13


def read_deck_list(path):
    """The `owner/name:path` rows of the list (blank lines and # comments skipped)."""
    decks = []
    for number, line in enumerate(Path(path).read_text().splitlines(), 1):
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        repo, sep, deck = line.partition(":")
        if not sep or "/" not in repo or not deck:
            sys.exit(f"{path}:{number}: expected owner/name:path, got '{line}'")
        decks.append((repo, deck))
    return decks


def git_dir(mirrors, repo):
    for mirror in mirrors:
        candidate = Path(mirror) / repo.replace("/", "+") / "repo"
        if candidate.exists():
            return candidate
    return None


def materialise(mirrors, repo, deck, into):
    """Writes the deck into `into` and returns (path, commit), or (None, why)."""
    directory = git_dir(mirrors, repo)
    if directory is None:
        return None, f"no mirror of {repo} under {', '.join(mirrors)}"
    git = ["git", f"--git-dir={directory}"]
    shown = subprocess.run(git + ["show", f"HEAD:{deck}"], capture_output=True)
    if shown.returncode != 0:
        return None, shown.stderr.decode(errors="replace").strip()
    commit = subprocess.run(git + ["rev-parse", "HEAD"], capture_output=True, text=True)
    into.mkdir(parents=True, exist_ok=True)
    path = into / Path(deck).name
    path.write_bytes(shown.stdout)
    return path, commit.stdout.strip()


def run(command, timeout):
    start = time.monotonic()
    try:
        done = subprocess.run(command, capture_output=True, text=True, timeout=timeout)
        code, output = done.returncode, done.stdout + done.stderr
    except subprocess.TimeoutExpired as expired:
        code = "timeout"
        output = (expired.stdout or b"").decode(errors="replace") if isinstance(
            expired.stdout, bytes) else (expired.stdout or "")
    return code, output, time.monotonic() - start


# "1+2+3      not converted: reason" (the summary row of `catena import moordyn`).
REFUSED = re.compile(r"^(\d+(?:\+\d+)*)\s+not converted: (.*)$")
# "1+2+3      DIR/x.toml  [line] 3 segments + [seabed]: grounded 113 m of 850 m" (the converted
# row since the importer reports the statics; older importers print the file alone).
CONVERTED = re.compile(r"^(\d+(?:\+\d+)*)\s+(\S+\.toml)\s+(.*?): (.*)$")


def import_deck(catena, deck_path, out, timeout):
    code, output, seconds = run([catena, "import", "moordyn", str(deck_path), "--out", str(out)],
                                timeout)
    refused, statics = [], {}
    for line in output.splitlines():
        match = REFUSED.match(line.strip())
        if match:
            refused.append({"lines": match.group(1), "reason": match.group(2).strip()})
        match = CONVERTED.match(line.strip())
        if match:
            statics[Path(match.group(2)).name] = {"tables": match.group(3),
                                                  "statics": match.group(4)}
    scenes = sorted(out.glob("*.toml")) if out.exists() else []
    return {"exit": code, "seconds": round(seconds, 3), "refused": refused,
            "scenes": [s.name for s in scenes], "statics": statics, "output": output[-6000:]}


def modes_of(report, solver):
    """{plane: [(omega, estimate)]} of `solver` in a `catena solve --json` report."""
    try:
        record = report["scenes"][0]["solvers"][solver]
    except (KeyError, IndexError, TypeError):
        return {}
    out = {}
    for plane in ("inplane", "outofplane"):
        modes = (record.get(plane) or {}).get("modes") or []
        out[plane] = [(m.get("omega_rad_s"), m.get("relative_error_estimate")) for m in modes]
    return out


def load_json(path):
    try:
        return json.loads(Path(path).read_text())
    except (OSError, ValueError):
        return None


def fe_against_shooting(default_report, reference_report):
    """Per mode: fe's relative difference from shooting at rtol 1e-13 and actual / estimate.

    Modes are paired within a plane by mutual nearest frequency, not by index, so that a mode one
    solver finds and the other does not shows up as unpaired instead of shifting every pair after
    it. Returns (pairs, unpaired) where unpaired lists the modes of either solver left over.
    """
    fe = modes_of(default_report, "fe") if default_report else {}
    shooting = modes_of(reference_report, "shooting") if reference_report else {}
    rows, unpaired = [], []
    for plane in ("inplane", "outofplane"):
        a = [(i, w, e) for i, (w, e) in enumerate(fe.get(plane, []), 1) if w]
        b = [(j, w) for j, (w, _) in enumerate(shooting.get(plane, []), 1) if w]
        if not a or not b:
            continue
        nearest_b = {i: min(b, key=lambda m: abs(m[1] - w)) for i, w, _ in a}
        nearest_a = {j: min(a, key=lambda m: abs(m[1] - w)) for j, w in b}
        paired_b = set()
        for i, omega_fe, estimate in a:
            j, omega_ref = nearest_b[i]
            if nearest_a[j][0] != i:
                unpaired.append({"solver": "fe", "plane": plane, "mode": i, "omega": omega_fe,
                                 "estimate": estimate})
                continue
            paired_b.add(j)
            difference = abs(omega_fe - omega_ref) / abs(omega_ref)
            ratio = difference / estimate if estimate and estimate > 0 else None
            rows.append({"plane": plane, "mode": i, "shooting_mode": j, "fe_omega": omega_fe,
                         "shooting_omega": omega_ref, "relative_difference": difference,
                         "fe_estimate": estimate, "ratio": ratio})
        # Shooting's modes above fe's highest are beyond fe's request, not missing from fe.
        top = max(w for _, w, _ in a)
        unpaired += [{"solver": "shooting", "plane": plane, "mode": j, "omega": w}
                     for j, w in b if j not in paired_b and w <= top]
    return rows, unpaired


def without_path(message):
    """A message without the temporary scene path it starts with ("error: /tmp/.../x.toml: ")."""
    return re.sub(r"(error: )?\S*\.toml: ", "", message)


def first_error(output):
    for line in output.splitlines():
        if "error" in line.lower() or "declin" in line.lower() or "refus" in line.lower():
            return without_path(line.strip())[:300]
    return ""


def solve_scene(catena, scene, work, time_limit):
    """The default solve and the shooting reference of one scene."""
    timeout = time_limit * 3 + 60 if time_limit else None
    limit = ["--time-limit", str(time_limit)] if time_limit else []
    default_json = work / (scene.stem + ".default.json")
    code, output, seconds = run([catena, "solve", str(scene), "--json", str(default_json), "-q"]
                                + limit, timeout)
    record = {"scene": scene.name, "exit": code, "seconds": round(seconds, 2)}
    if code not in (0, 1):
        record["error"] = first_error(output) or output.strip()[-300:]
    reference = work / (scene.stem + ".reference.toml")
    reference.write_text(scene.read_text() +
                         f"\n[solvers]\nshooting = {{ rtol = {REFERENCE_RTOL:g} }}\n")
    reference_json = work / (scene.stem + ".reference.json")
    ref_code, ref_output, ref_seconds = run(
        [catena, "solve", str(reference), "--json", str(reference_json), "-q"] + limit, timeout)
    record["reference_exit"] = ref_code
    record["reference_seconds"] = round(ref_seconds, 2)
    default_report = load_json(default_json)
    record["checks_failed"] = failed_checks(default_report)
    record["fe_vs_shooting"], record["unpaired_modes"] = fe_against_shooting(
        default_report, load_json(reference_json))
    if not record["fe_vs_shooting"]:
        record["fe_vs_shooting_missing"] = why_no_comparison(default_report,
                                                             load_json(reference_json))
    return record


def failed_checks(report):
    """The checks of a default solve whose verdict is FAIL or SOURCE."""
    try:
        table = report["scenes"][0]["checks"]
    except (KeyError, IndexError, TypeError):
        return []
    rows = [dict(zip(table["fields"], row)) for row in table.get("rows", [])]
    return [f"{r['check']} {r['compare']} {r.get('plane', '')} {r.get('mode', '')}: {r['verdict']}"
            for r in rows if r.get("verdict") in ("FAIL", "SOURCE")]


def why_no_comparison(default_report, reference_report):
    """Why fe and shooting were not compared: a solver's termination and message."""
    reasons = []
    for label, report, solver in (("fe", default_report, "fe"),
                                  ("shooting 1e-13", reference_report, "shooting")):
        try:
            scene = report["scenes"][0]
        except (KeyError, IndexError, TypeError):
            reasons.append(f"{label}: no report")
            continue
        if scene.get("error"):
            reasons.append(f"{label}: {without_path(scene['error'])}"[:240])
            continue
        summary = ((scene.get("solvers") or {}).get(solver) or {}).get("summary")
        if not summary:
            reasons.append(f"{label}: did not run")
        else:
            reasons.append(f"{label}: {summary.get('termination')} "
                           f"{summary.get('message', '')}"[:240])
    return "; ".join(reasons)


def corpus_deck(catena, mirrors, repo, deck, root, time_limit):
    slug = (repo + "/" + deck).replace("/", "_")
    work = root / slug
    path, commit = materialise(mirrors, repo, deck, work / "deck")
    record = {"repo": repo, "deck": deck}
    if path is None:
        record["unavailable"] = commit
        return record
    record["commit"] = commit
    imported = import_deck(catena, path, work / "scenes", 120)
    record["import"] = imported
    record["solves"] = [solve_scene(catena, work / "scenes" / name, work, time_limit)
                        for name in imported["scenes"]]
    return record


def fmt(value, spec):
    return format(value, spec) if isinstance(value, (int, float)) else "-"


def short(deck):
    return deck.rsplit("/", 1)[-1] if deck.count("/") < 2 else "/".join(deck.split("/")[-2:])


def markdown(records, meta):
    t = meta["totals"]
    out = [f"Corpus of {len(records)} published MoorDyn decks, {meta['date']}, "
           f"{meta['version']}; per-solve time limit {meta['time_limit']} s. "
           f"{t['decks_read']} decks read, {t['scenes']} scenes written, {t['refused_rows']} "
           f"summary rows not converted; `catena solve` exit codes {t['solve_exit_codes']}; fe "
           f"against shooting at rtol 1e-13 on {t['modes_compared']} modes: actual / estimate "
           f"at most {fmt(t['max_ratio'], '.3g')}, {t['modes_over_estimate']} modes at or over 1; "
           f"{t['unpaired_modes']} modes one solver found and the other did not.",
           ""]
    out += ["| deck | import | converted (statics at import): solve exit (s) | refused (reason) |",
            "|---|---|---|---|"]
    for r in records:
        name = f"{r['repo']} `{r['deck']}`"
        if "unavailable" in r:
            out.append(f"| {name} | not available | - | {r['unavailable']} |")
            continue
        imp = r["import"]
        words = imp.get("statics", {})
        solves = ", ".join(
            f"{s['scene'].rsplit('-line-', 1)[-1][:-5]}"
            + (f" ({words[s['scene']]['statics']})" if s["scene"] in words else "")
            + f": {s['exit']} ({s['seconds']:.1f})" for s in r["solves"]) or "-"
        refused = "; ".join(f"{x['lines']}: {x['reason']}" for x in imp["refused"]) or "-"
        out.append(f"| {name} | {imp['exit']} | {solves} | {refused.replace('|', '/')} |")
    out += ["", "fe against shooting at rtol 1e-13, the scenes with anything to say (actual / estimate "
            "above 0.1, a mode one solver did not find, a failed default check, or no comparison); "
            "every other scene: all modes paired, actual / estimate <= 0.1 (corpus.json has "
            "every mode):", "",
            "| scene | modes paired | max rel. difference | max actual / estimate | unpaired modes "
            "(solver plane mode: rad/s) | default checks FAIL |",
            "|---|---|---|---|---|---|"]
    for r in records:
        for s in r.get("solves", []):
            rows = s["fe_vs_shooting"]
            worst = max((x["relative_difference"] for x in rows), default=None)
            ratios = [x["ratio"] for x in rows if x["ratio"] is not None]
            ratio = max(ratios, default=None)
            if (rows and (ratio is None or ratio <= 0.1) and not s.get("unpaired_modes")
                    and not s["checks_failed"]):
                continue
            note = "" if rows else " (" + s.get("fe_vs_shooting_missing", "") + ")"
            unpaired = ", ".join(f"{u['solver']} {u['plane']} {u['mode']}: {u['omega']:.6g}"
                                 for u in s.get("unpaired_modes", [])) or "-"
            out.append(f"| {short(r['deck'])}: {s['scene']} | {len(rows)}{note.replace('|', '/')} | "
                       f"{fmt(worst, '.2e')} | {fmt(ratio, '.3g')} | {unpaired} | "
                       f"{len(s['checks_failed'])} |")
    return "\n".join(out) + "\n"


def changes(records, before):
    """Markdown rows for each scene whose solve exit code or statics words differ from `before`
    (a corpus.json of an earlier run), and scenes written by one run only."""
    def scenes_of(recs):
        out = {}
        for r in recs:
            words = r.get("import", {}).get("statics", {})
            for s in r.get("solves", []):
                ratios = [x["ratio"] for x in s["fe_vs_shooting"] if x["ratio"] is not None]
                out[(r["repo"], r["deck"], s["scene"])] = (
                    s["exit"], words.get(s["scene"], {}).get("statics", "-"),
                    max(ratios, default=None))
        return out
    old, new = scenes_of(before["decks"]), scenes_of(records)
    rows = ["| deck: scene | before: exit, max actual/estimate | now: exit (statics at import), "
            "max actual/estimate |", "|---|---|---|"]
    for key in sorted(set(old) | set(new)):
        a, b = old.get(key), new.get(key)
        over = [x is not None and x >= 1.0 for x in (a[2] if a else None, b[2] if b else None)]
        if a and b and a[0] == b[0] and over[0] == over[1]:
            continue
        label = f"{short(key[1])}: {key[2]}"
        before_text = f"{a[0]}, {fmt(a[2], '.3g')}" if a else "not written"
        now_text = f"{b[0]} ({b[1]}), {fmt(b[2], '.3g')}" if b else "not written"
        rows.append(f"| {label} | {before_text} | {now_text.replace('|', '/')} |")
    return rows


def totals(records):
    scenes = [s for r in records for s in r.get("solves", [])]
    ratios = [x["ratio"] for s in scenes for x in s["fe_vs_shooting"] if x["ratio"] is not None]
    exits = {}
    for s in scenes:
        exits[str(s["exit"])] = exits.get(str(s["exit"]), 0) + 1
    return {"decks": len(records),
            "decks_read": sum(1 for r in records if r.get("import", {}).get("exit") == 0),
            "scenes": len(scenes),
            "refused_rows": sum(len(r.get("import", {}).get("refused", [])) for r in records),
            "solve_exit_codes": exits,
            "modes_compared": len(ratios),
            "modes_over_estimate": sum(1 for x in ratios if x >= 1.0),
            "unpaired_modes": sum(len(s.get("unpaired_modes", [])) for s in scenes),
            "max_ratio": max(ratios, default=None),
            "max_relative_difference": max((x["relative_difference"] for s in scenes
                                            for x in s["fe_vs_shooting"]), default=None)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--catena", default=str(REPO_ROOT / "build" / "catena"))
    parser.add_argument("--decks", default=str(DEFAULT_DECKS))
    parser.add_argument("--out", required=True)
    parser.add_argument("--mirror", action="append",
                        help="directory holding <owner>+<name>/repo git dirs (repeatable; "
                             "default /work/.mirror and /work/corpus-mirror)")
    parser.add_argument("-j", type=int, default=1, help="decks solved in parallel")
    parser.add_argument("--before", help="corpus.json of an earlier run: list the scenes whose "
                                         "solve exit code or fe-vs-shooting ratio changed")
    parser.add_argument("--time-limit", type=float, default=120.0,
                        help="catena solve --time-limit for each solve [s] (0: none)")
    args = parser.parse_args()
    mirrors = args.mirror or ["/work/.mirror", "/work/corpus-mirror"]
    catena = str(Path(args.catena).resolve())
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    version = subprocess.run([catena, "--version"], capture_output=True, text=True).stdout.strip()
    decks = read_deck_list(args.decks)
    root = Path(tempfile.mkdtemp(prefix="moordyn-corpus-"))
    start = time.monotonic()
    with concurrent.futures.ThreadPoolExecutor(max_workers=max(1, args.j)) as pool:
        futures = [pool.submit(corpus_deck, catena, mirrors, repo, deck, root, args.time_limit)
                   for repo, deck in decks]
        records = []
        for future, (repo, deck) in zip(futures, decks):
            records.append(future.result())
            print(f"{repo}:{deck} done ({time.monotonic() - start:.0f} s)", flush=True)
    meta = {"date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "version": version, "time_limit": args.time_limit, "work": str(root),
            "seconds": round(time.monotonic() - start, 1), "totals": totals(records)}
    (out / "corpus.json").write_text(json.dumps({"meta": meta, "decks": records}, indent=1))
    text = markdown(records, meta)
    if args.before:
        before = json.loads(Path(args.before).read_text())
        text += (f"\nChanged against {args.before} ({before['meta']['version']}, "
                 f"{before['meta']['date']}):\n\n" + "\n".join(changes(records, before)) + "\n")
    (out / "corpus.md").write_text(text)
    print(f"deck list: {args.decks}; mirrors: {', '.join(mirrors)}")
    print(json.dumps(meta["totals"], indent=1))
    print(f"wrote {out / 'corpus.md'} and {out / 'corpus.json'} in {meta['seconds']} s; "
          f"scenes and reports kept in {root}")


if __name__ == "__main__":
    main()
