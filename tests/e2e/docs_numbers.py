#!/usr/bin/python3
"""Numbers and names in README.md, docs/, schemas/ and python/README.md that the code defines, checked
against the code (issue 35: "every number in README and docs that the code can produce is produced by
the code or checked by a test").

docs_numbers.py PART HAPTEX ROOT, PART one of:
  formats   docs/architecture.md's format table, each JSON schema's format and every FAMILY/N named
            anywhere against `haptex --json --version` (no version later than the one haptex writes)
  defaults  option values in usage lines ("[--repeats 10]") and in prose ("`--hop` samples (default
            100", "`--reference-frames` takes 10 to 250") against each command's --help
  paths     every repository path a doc names in back-quotes exists (a moved or renamed file)
  commands  every `haptex WORD ...` in a code block is a command haptex has
  demo      (one more argument: a folder examples/demo/run.sh filled) the figures README.md,
            docs/benchmark.md, docs/predict.md, docs/capture.md and docs/render.md quote from `make demo`
            are the ones this demo gives, at the precision they are printed (times excepted)
  hatt      (one more argument: a folder `examples/demo/run.sh HAPTEX OUT hatt --models ... --images ...`
            filled from ../shared/data/hatt) docs/evaluate.md's figures of the 60 HaTT-driven materials
Prints one line per mismatch (file:line: what the doc says, what the code says) and exits 1 if any.
"""
import json
import pathlib
import re
import subprocess
import sys
import tempfile

DOCS = ["README.md", "python/README.md", "bench/README.md", "capture/README.md"]
NUMBER = re.compile(r"^-?[0-9]+(\.[0-9]+)?([eE]-?[0-9]+)?$")
WITH_SUBCOMMANDS = {"capture", "convert", "synth"}


def doc_files(root):
    files = [root / d for d in DOCS if (root / d).exists()]
    files += sorted((root / "docs").glob("*.md")) + sorted((root / "schemas").glob("*.md"))
    return files


def lines_of(root):
    for path in doc_files(root):
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            yield path.relative_to(root), number, line


def code_lines(root):
    """Lines inside ``` blocks."""
    for path in doc_files(root):
        inside = False
        for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if line.lstrip().startswith("```"):
                inside = not inside
            elif inside:
                yield path.relative_to(root), number, line


def run(argv):
    return subprocess.run(argv, capture_output=True, text=True, check=False)


def help_text(haptex, command):
    result = run([haptex] + command + ["--help"])
    return result.stdout if result.returncode == 0 else None


def commands(haptex):
    """{"train": [], "capture": ["record", ...], ...} from the help pages."""
    def listed(text):
        part = text.split("Subcommands:", 1)
        if len(part) < 2:
            return []
        return [m.group(1) for m in re.finditer(r"^  ([a-z][a-z-]*)\b", part[1].split("\n\n")[0], re.M)]

    return {name: listed(help_text(haptex, [name]) or "") for name in listed(help_text(haptex, []))}


def option_facts(text):
    """{"--repeats": {"default": "10", "range": ("2", "1000")}} from one --help page."""
    facts = {}
    for line in text.splitlines():
        m = re.match(r"^\s+(?:-\w,)?(--[a-z0-9-]+)(?:,-\w)?\s(.*)$", line)
        if not m:
            continue
        spec, *description = re.split(r"\s{2,}", m.group(2).strip(), maxsplit=1)
        fact = {}
        d = re.search(r"=(\S+)$", spec)
        if d:
            fact["default"] = d.group(1)
        r = re.search(r"in \[(\S+) - (\S+)\]", spec) or re.search(r"\(([0-9.]+) to ([0-9.]+)\)", " ".join(description))
        if r:
            fact["range"] = (r.group(1), r.group(2))
        facts[m.group(1)] = fact
    return facts


def same_value(doc, code):
    if NUMBER.match(doc) and NUMBER.match(code):
        return float(doc) == float(code)
    return doc == code


def check_formats(haptex, root):
    formats = json.loads(run([haptex, "--json", "--version"]).stdout)["formats"]
    current = {}
    for names in formats.values():
        for name in names:
            family, version = name.split("/")
            current[family] = int(version)
    bad = []
    table = {}
    text = (root / "docs/architecture.md").read_text(encoding="utf-8")
    for m in re.finditer(r"^\| `([a-z-]+)` \| ([0-9]+) \| `haptex ", text, re.M):
        table[m.group(1)] = int(m.group(2))
    written = {n.split("/")[0]: int(n.split("/")[1]) for n in formats["hdf5_written"]}
    if table != written:
        bad.append(f"docs/architecture.md: the format table says {table}, haptex --json --version writes {written}")
    for schema in sorted((root / "schemas").glob("*.schema.json")):
        declared = json.loads(schema.read_text(encoding="utf-8")).get("properties", {}).get("format", {}).get("const")
        # A format haptex only reads (tactile-sensors/1) has its one home in its schema.
        family = (declared or "").split("/")[0]
        if family in current and declared != f"{family}/{current[family]}":
            bad.append(f"{schema.relative_to(root)}: format const {declared}, haptex writes {family}/{current[family]}")
    for path, number, line in lines_of(root):
        for m in re.finditer(r"\b([a-z][a-z-]*)/([0-9]+)\b", line):
            family, version = m.group(1), int(m.group(2))
            if family in current and version > current[family]:
                bad.append(f"{path}:{number}: {family}/{version}, but haptex writes {family}/{current[family]}")
    return bad


def usage_values(root, known):
    """(path, line, command, option, value) of "[--opt VALUE]" in usage lines of code blocks."""
    command = None
    for path, number, line in code_lines(root):
        words = line.split()
        if len(words) >= 2 and words[0] == "haptex" and words[1] in known:
            command = words[1:3] if words[1] in WITH_SUBCOMMANDS and len(words) > 2 else words[1:2]
        elif not line.startswith((" ", "\t")):
            command = None
        if command is None:
            continue
        for m in re.finditer(r"\[(--[a-z0-9-]+)[ =]([^\]\s|]+)\]", line):
            yield path, number, command, m.group(1), m.group(2)


def prose_values(root):
    """(path, line, option, kind, values) of "`--opt ...` ... (default V" and "`--opt` takes A to B"."""
    for path, number, line in lines_of(root):
        for m in re.finditer(r"`(--[a-z0-9-]+)[^`]*`[^`.;]{0,40}?\(default ([0-9.]+)[,;) ]", line):
            yield path, number, m.group(1), "default", (m.group(2),)
        for m in re.finditer(r"`(--[a-z0-9-]+) ([0-9.]+)`, the default\b", line):
            yield path, number, m.group(1), "default", (m.group(2),)
        for m in re.finditer(r"`(--[a-z0-9-]+)` takes ([0-9.]+) to ([0-9.]+)", line):
            yield path, number, m.group(1), "range", (m.group(2), m.group(3))


def all_option_facts(haptex, known):
    """{("capture", "record"): facts, ("train",): facts, ...}"""
    pages = {}
    for name, subs in known.items():
        for command in ([[name, s] for s in subs] or [[name]]):
            pages[tuple(command)] = option_facts(help_text(haptex, command) or "")
    return pages


def check_defaults(haptex, root):
    known = commands(haptex)
    pages = all_option_facts(haptex, known)
    bad, checked = [], 0
    for path, number, command, option, value in usage_values(root, known):
        facts = pages.get(tuple(command), {})
        if re.match(r"^[A-Z_]+$", value):  # a placeholder (NAME), not a value
            continue
        if option not in facts:
            bad.append(f"{path}:{number}: haptex {' '.join(command)} has no option {option}")
        elif "default" in facts[option] and (NUMBER.match(value) or not NUMBER.match(facts[option]["default"])):
            checked += 1
            if not same_value(value, facts[option]["default"]):
                bad.append(f"{path}:{number}: [{option} {value}], but haptex {' '.join(command)} --help says {option}={facts[option]['default']}")
    for path, number, option, kind, values in prose_values(root):
        # Prose names no command: the option's facts on every page that has it must agree with the doc.
        found = [(c, f[option]) for c, f in pages.items() if option in f]
        if not found:
            bad.append(f"{path}:{number}: no command has {option}")
        for command, fact in found:
            if kind in fact:
                checked += 1
                code = fact[kind] if kind == "range" else (fact[kind],)
                if not all(same_value(d, c) for d, c in zip(values, code)):
                    bad.append(f"{path}:{number}: {option} {kind} {values}, but haptex {' '.join(command)} --help says {code}")
    if checked < 15:
        bad.append(f"only {checked} option values found in the docs: the patterns no longer match what the docs write")
    return bad


def check_paths(root):
    tops = {p.name for p in root.iterdir() if p.is_dir() and not p.name.startswith(".") and p.name != "build"}
    bad, checked = [], 0
    for path, number, line in lines_of(root):
        for m in re.finditer(r"`([^`\s]+)`", line):
            word = m.group(1).rstrip(".,;:")
            candidate = word.split(":")[0]
            first = candidate.split("/")[0]
            if first not in tops or "/" not in candidate or re.search(r"[<>*{}$]|\.\.\.|[A-Z]{2,}", candidate):
                continue
            if not re.search(r"\.[a-z]+$|/$", candidate):  # a file (with an extension) or a folder
                continue
            checked += 1
            if not (root / candidate).exists():
                bad.append(f"{path}:{number}: `{word}` names {candidate}, which is not in the repository")
    if checked < 20:
        bad.append(f"only {checked} repository paths found in the docs: the pattern no longer matches")
    return bad


def check_commands(haptex, root):
    known = commands(haptex)
    bad = []
    for path, number, line in code_lines(root):
        words = re.sub(r"^\s*(\$ )?", "", line).split()
        if len(words) < 2 or words[0] != "haptex" or words[1].startswith("-") or words[1].endswith(":"):
            continue
        if words[1] not in known:
            bad.append(f"{path}:{number}: haptex {words[1]} is not a command")
        elif known[words[1]] and len(words) > 2 and not words[2].startswith("-") and words[2] not in known[words[1]]:
            bad.append(f"{path}:{number}: haptex {words[1]} {words[2]} is not a command")
    return bad


def median(values):
    v = sorted(values)
    n = len(v)
    return v[n // 2] if n % 2 else (v[n // 2 - 1] + v[n // 2]) / 2


class DemoFacts:
    """The demo's figures as the docs print them."""

    def __init__(self, demo, root):
        self.demo, self.root = demo, root
        self.results = json.loads((demo / "report/results.json").read_text(encoding="utf-8"))
        self.log = json.loads((demo / "model.training.json").read_text(encoding="utf-8"))
        self.floors = {f["id"]: f for f in self.results["floors"]}

    def experiment(self, name):
        return next(e for e in self.results["experiments"] if e["id"] == name)

    def over_input_floor(self, name):
        ratios = [m["model"] / self.floors[m["id"]]["input_floor"] for m in self.experiment(name)["materials"]]
        return median(ratios)

    def worst(self, name):
        m = max(self.experiment(name)["materials"], key=lambda m: m["floor_ratio"])
        return m["floor_ratio"], m["name"]

    def table_row(self, name):
        e = self.experiment(name)
        t = e["totals"]
        return [f"{e['mean_model']:.3f}", f"{e['median_floor_ratio']:.2f}", f"{e['worst_floor_ratio']:.2f}", str(t["better"]),
                str(t["materials"]), str(t["significantly_better"])]


def demo_checks(facts):
    """(doc, pattern, expected groups): each pattern's groups must read the expected strings."""
    input_ratios = [f["input_floor"] / f["distance"] for f in facts.floors.values()]
    unified, per_material = "unified-new-actions", "per-material"
    worst, worst_name = facts.worst(unified)
    windows = sum(m["windows"] for m in facts.experiment(unified)["materials"])
    n = str(len(facts.floors))
    return [
        ("README.md", r"whole pipeline on ([0-9]+) synthetic materials", [n]),
        ("docs/benchmark.md", r"`make demo`: ([0-9]+) synthetic materials, ([0-9]+) test windows", [n, str(windows)]),
        ("docs/benchmark.md", r"\| `unified-new-actions` \(haptex train, defaults\) \| ([0-9.]+) \| ([0-9.]+) / ([0-9.]+) \| ([0-9]+) of ([0-9]+) \(([0-9]+)\)",
         facts.table_row(unified)),
        ("docs/benchmark.md", r"\| `per-material` \(haptex train --per-material\) \| ([0-9.]+) \| ([0-9.]+) / ([0-9.]+) \| ([0-9]+) of ([0-9]+) \(([0-9]+)\)",
         facts.table_row(per_material)),
        ("docs/benchmark.md", r"model is below both and within 10 % on ([0-9]+) of ([0-9]+)",
         [str(facts.experiment(unified)["totals"]["within_floor_10_percent"]), n]),
        ("docs/benchmark.md", r"is ([0-9.]+) times the oracle\s+at the median over the ([0-9]+) materials and ([0-9.]+) at worst",
         [f"{median(input_ratios):.2f}", n, f"{max(input_ratios):.2f}"]),
        ("docs/benchmark.md", r"haptex's unified model ([0-9.]+) \(", [f"{facts.over_input_floor(unified):.3f}"]),
        ("docs/benchmark.md", r"the per-material models ([0-9.]+) \(", [f"{facts.over_input_floor(per_material):.3f}"]),
        ("docs/predict.md", r"\| 7 bins \(the default\) \| ([0-9.]+) \| ([0-9.]+) \| ([0-9.]+) \| ([0-9]+) \| ([0-9.]+) \(([A-Za-z0-9 ]+)\) \| ([0-9.]+) \|",
         [f"{facts.log['metrics']['spectrum']['val_distance']:.4f}", f"{facts.experiment(unified)['mean_model']:.3f}",
          f"{facts.experiment(unified)['median_floor_ratio']:.3f}", str(facts.experiment(unified)["totals"]["within_floor_10_percent"]),
          f"{worst:.2f}", worst_name, f"{facts.over_input_floor(unified):.3f}"]),
        ("docs/capture.md", r"The demo's ([0-9]+) synthetic presses", [str(sum(1 for _ in (facts.demo / "synth/gelsight").rglob("*.avi")))]),
        ("docs/capture.md", r"make a ([0-9]+) MB gelsight file", [str(round((facts.demo / "gelsight.h5").stat().st_size / 1e6))]),
    ]


def hatt_checks(facts):
    """docs/evaluate.md's "Where the models stand" table and the input floor's sentence."""
    def row(name):
        e = facts.experiment(name)
        t = e["totals"]
        w = max(e["materials"], key=lambda m: m["floor_ratio"])
        lsd = median([m["model_lsd_db"] for m in e["materials"]])
        return [f"{e['mean_model']:.3f}", f"{e['median_floor_ratio']:.3f}", str(t["within_floor_10_percent"]),
                str(t["within_floor_15_percent"]), f"{w['floor_ratio']:.2f}", w["name"], f"{lsd:.2f}"]

    cells = r"\| ([0-9.]+) \| ([0-9.]+) \| ([0-9]+) \| ([0-9]+) \| ([0-9.]+) \(([A-Za-z0-9 ]+)\) \| ([0-9.]+) dB \|"
    unified = facts.experiment("unified-new-actions")
    oracle = [f["distance"] for f in facts.floors.values()]
    input_ratios = [f["input_floor"] / f["distance"] for f in facts.floors.values()]
    over_input = [m["model"] / facts.floors[m["id"]]["input_floor"] for m in unified["materials"]]
    doc = "docs/evaluate.md"
    u, presses = row("unified-new-actions"), facts.experiment("unified-new-presses")["totals"]
    default_row = [f"{facts.log['metrics']['spectrum']['val_distance']:.4f}", *u[:4], u[4], u[5], u[6], f"{median(over_input):.3f}",
                   str(presses["within_floor_10_percent"]), str(presses["within_floor_15_percent"])]
    return [
        ("docs/predict.md", r"\| \*\*7 bins \(the default\)\*\* \| \*\*([0-9.]+)\*\* \| \*\*([0-9.]+)\*\* \| \*\*([0-9.]+)\*\* \| \*\*([0-9]+)\*\* \| "
         r"\*\*([0-9]+)\*\* \| ([0-9.]+) \(([A-Za-z0-9 ]+)\) \| \*\*([0-9.]+) dB\*\* \| \*\*([0-9.]+)\*\* \| ([0-9]+) / ([0-9]+) \|", default_row),
        (doc, r"oracle mean\s+distance ([0-9.]+) m/s\^2", [f"{sum(oracle) / len(oracle):.3f}"]),
        (doc, r"\| unified, new actions " + cells, row("unified-new-actions")),
        (doc, r"\| unified, new press \(recognised\) " + cells, row("unified-new-presses")),
        (doc, r"\| per-material " + cells, row("per-material")),
        (doc, r"\| stitched, FGLA 100 \| ([0-9.]+) \| ([0-9.]+) \| ([0-9]+) \| ([0-9]+) \| ([0-9.]+) \(([A-Za-z0-9 ]+)\) \| ([0-9.]+) dB \|",
         row("stitched-fgla")),
        (doc, r"\| AR \(refit\) rendered \| ([0-9.]+) \|", [f"{unified['mean_baseline']:.3f}"]),
        (doc, r"The oracle's own LSD is ([0-9.]+) dB", [f"{median([f['lsd_db'] for f in facts.floors.values()]):.2f}"]),
        (doc, r"On the 60\s+HaTT-driven materials it is ([0-9.]+) times the oracle \(median; ([0-9.]+) to ([0-9.]+), above 1.05 on ([0-9]+);",
         [f"{median(input_ratios):.3f}", f"{min(input_ratios):.3f}", f"{max(input_ratios):.3f}", str(sum(r > 1.05 for r in input_ratios))]),
        (doc, r"the unified model is within 10 % of the input\s+floor on ([0-9]+) materials, within 5 % on ([0-9]+) \(median ([0-9.]+);",
         [str(sum(r <= 1.10 for r in over_input)), str(sum(r <= 1.05 for r in over_input)), f"{median(over_input):.3f}"]),
    ]


def check_figures(facts, checks):
    bad = []
    for doc, pattern, expected in checks:
        text = (facts.root / doc).read_text(encoding="utf-8")
        m = re.search(pattern, text)
        if not m:
            bad.append(f"{doc}: no text matches {pattern!r}: the doc changed; keep the check with it")
        elif list(m.groups()) != expected:
            bad.append(f"{doc}:{text[: m.start()].count(chr(10)) + 1}: the doc says {list(m.groups())}, the run gives {expected}")
    return bad


def render_example(haptex, root, facts):
    """docs/render.md's example, run on the demo: its printed lines, with the compute time masked."""
    text = (root / "docs/render.md").read_text(encoding="utf-8")
    block = re.search(r"```\n\$ # make demo's build/demo/dataset.h5 and model.h5.*?\n```", text, re.S).group(0)
    bad = []
    commands = [(line[2:], next_line) for line, next_line in zip(block.splitlines(), block.splitlines()[1:])
                if line.startswith("$ haptex ")]
    work = tempfile.mkdtemp(prefix="docs-example-", dir=facts.demo)
    for command, expected in commands:
        argv = [haptex] + command.split()[1:]
        argv = [str(facts.demo / a) if a in ("dataset.h5", "model.h5") else a for a in argv]
        result = subprocess.run(argv, capture_output=True, text=True, cwd=work, check=False)
        mask = lambda line: re.sub(r"[0-9.]+ s compute per s", "T s compute per s", line.strip())
        if mask(result.stdout + result.stderr) != mask(expected):
            bad.append(f"docs/render.md: `{command}` prints\n  {(result.stdout + result.stderr).strip()}\nthe doc says\n  {expected}")
    if len(commands) < 2:
        bad.append("docs/render.md: the demo example has fewer than 2 commands: the pattern no longer matches")
    return bad


def check_demo(haptex, root, demo):
    facts = DemoFacts(demo, root)
    return check_figures(facts, demo_checks(facts)) + render_example(haptex, root, facts)


def check_hatt(root, run):
    facts = DemoFacts(run, root)
    if len(facts.floors) != 60:
        return [f"{run}: {len(facts.floors)} materials, not the 60 HaTT-driven ones docs/evaluate.md quotes"]
    return check_figures(facts, hatt_checks(facts))

def main():
    part, haptex, root = sys.argv[1], str(pathlib.Path(sys.argv[2]).resolve()), pathlib.Path(sys.argv[3]).resolve()
    checks = {
        "formats": lambda: check_formats(haptex, root),
        "defaults": lambda: check_defaults(haptex, root),
        "paths": lambda: check_paths(root),
        "commands": lambda: check_commands(haptex, root),
        "demo": lambda: check_demo(haptex, root, pathlib.Path(sys.argv[4]).resolve()),
        "hatt": lambda: check_hatt(root, pathlib.Path(sys.argv[4]).resolve()),
    }
    bad = checks[part]()
    if "-v" in sys.argv:
        print(f"{part}: {len(bad)} mismatches", file=sys.stderr)
    for line in bad:
        print(line)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
