#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""The HTML report in a real browser: renders report.html with headless Chromium and checks that
the summary, the source-discrepancy section, the per-scene tables and the figures are there and
that every embedded figure decoded (naturalWidth > 0).

Usage: report_browser_test.py CATENA_CLI RESULTS_JSON OUT_DIR
Exit 77 (ctest: skipped) when Chromium is not installed.
"""
import pathlib
import re
import shutil
import subprocess
import sys
import tempfile

SKIP = 77


def main():
    cli, results, out = sys.argv[1], sys.argv[2], pathlib.Path(sys.argv[3])
    browser = shutil.which("chromium") or shutil.which("chromium-browser")
    if not browser:
        print("SKIPPED: chromium is not installed (apt-get install chromium to run this test)")
        return SKIP
    subprocess.run([cli, "report", "--from", results, "--out", str(out)], check=True)
    html = out / "report.html"
    # A script in the page records what rendered; --dump-dom prints the DOM after it ran.
    probe = html.read_text().replace(
        "</body>",
        "<script>window.addEventListener('load',()=>{const imgs=[...document.images];"
        "document.body.setAttribute('data-images',imgs.length);"
        "document.body.setAttribute('data-decoded',imgs.filter(i=>i.naturalWidth>0).length);"
        "document.body.setAttribute('data-tables',document.querySelectorAll('table').length);});</script></body>")
    with tempfile.TemporaryDirectory() as tmp:
        page = pathlib.Path(tmp) / "probe.html"
        page.write_text(probe)
        dom = subprocess.run(
            [browser, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
             "--disable-background-networking", "--disable-component-update", "--disable-sync",
             f"--user-data-dir={tmp}/profile", "--virtual-time-budget=5000", "--dump-dom", page.as_uri()],
            capture_output=True, text=True, timeout=120).stdout
    def attribute(name):
        match = re.search(rf'data-{name}="(\d+)"', dom)
        return int(match.group(1)) if match else -1
    images, decoded, tables = attribute("images"), attribute("decoded"), attribute("tables")
    print(f"rendered: {tables} tables, {images} figures, {decoded} decoded")
    failures = []
    for section in ["Catena verification report", "Source discrepancies", "Failures and warnings", "Solvers",
                    "Figures", "Scenes"]:
        if section not in dom:
            failures.append(f"section '{section}' missing")
    expected_figures = ["irvine-horizontal.png", "inclined-crossover.png", "mode-shapes.png",
                        "gale-b-3-hb0.00.png", "gale-b-4-hb0.00.png", "gale-c-2-curve-hb0.00-sag0.90.png"]
    index = (out / "figures" / "index.json").read_text() if (out / "figures" / "index.json").exists() else ""
    for name in expected_figures:
        if name not in index:
            failures.append(f"figure {name} not drawn")
    if images < len(expected_figures) or decoded != images:
        failures.append(f"{images} images, {decoded} decoded")
    if tables < 10:
        failures.append(f"only {tables} tables")
    for failure in failures:
        print("FAILED:", failure)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
