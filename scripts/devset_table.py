#!/usr/bin/env python3
"""The development set's table from cuetrack-bench --json: one row per sequence, one
column per tracker entry (mean overlap over seeds, %), then the averages, their
seed-to-seed spread, hit rate, AUC and precision at 20 px. With two or more cuetrack
entries, the last column is the first minus the second, '*' where the difference is
larger than the spread of either (the team's rule for a change: docs/algorithm.md).
Each --group LABEL:FIRST:COUNT prints first a line with the average over those sequences
(the real videos: the figure that counts; the randomised RGB-D group), each tracker's
overlap with its seed spread and hit rate.
Usage: devset_table.py [--group LABEL:FIRST:COUNT ...] DEVSET.json [OUT.md]"""
import json
import statistics
import sys


def fmt(v, d=1):
    return "n/a" if v is None else f"{v:.{d}f}"


def group_line(entries, labels, name, first, n):
    """The average of sequences first..first+n-1 per tracker: overlap (seed spread), hit rate."""
    parts = []
    for e, l in zip(entries, labels):
        seqs = [s for s in e["sequences"][first:first + n] if s["overlap"] is not None]
        if not seqs:
            parts.append(f"{l} not run")
            continue
        # A sequence a tracker cannot start on scores 0 (it gives no track).
        over = sum(s["overlap"] for s in seqs) / n
        hit = sum(s["hit"] for s in seqs) / n
        runs = [s["overlap_runs"] for s in seqs if s.get("overlap_runs")]
        spread = ""
        if runs and len(runs) == len(seqs) and min(len(r) for r in runs) > 1:
            k = min(len(r) for r in runs)
            per_seed = [sum(r[i] for r in runs) / n for i in range(k)]
            spread = f" (spread {statistics.stdev(per_seed):.2f})"
        parts.append(f"{l} {over:.2f}{spread} hit {hit:.2f}")
    return f"{name} ({n}): overlap / hit rate [%]: " + "; ".join(parts)


def main():
    groups = []
    while len(sys.argv) > 2 and sys.argv[1] == "--group":
        name, first, n = sys.argv[2].rsplit(":", 2)
        groups.append((name, int(first), int(n)))
        del sys.argv[1:3]
    entries = json.load(open(sys.argv[1]))
    if isinstance(entries, dict):
        entries = [entries]
    label = [e["tracker"] if e["config"] == "default" else
             ("" if e["tracker"] == "cuetrack" else e["tracker"] + " ") + e["config"]
             for e in entries]
    label = [l.replace("opencv-", "") for l in label]
    ours = [i for i, e in enumerate(entries) if e["tracker"] == "cuetrack"]
    delta = len(ours) >= 2
    names = [s["name"] for s in entries[0]["sequences"]]
    head = ["sequence"] + label + ([f"{label[ours[0]]} - {label[ours[1]]}"] if delta else [])
    rows = []
    for k, name in enumerate(names):
        row = [name]
        for e in entries:
            s = e["sequences"][k]
            row.append(fmt(s["overlap"]) if s["overlap"] is not None else "not run")
        if delta:
            a, b = entries[ours[0]]["sequences"][k], entries[ours[1]]["sequences"][k]
            if a["overlap"] is None or b["overlap"] is None:
                row.append("")
            else:
                d = a["overlap"] - b["overlap"]
                spread = max(a["overlap_spread"] or 0, b["overlap_spread"] or 0)
                row.append(f"{d:+.1f}" + ("*" if abs(d) > spread else ""))
        rows.append(row)
    avg = [e["average"] for e in entries]
    summary = [
        ["average overlap"] + [fmt(a["overlap"], 2) for a in avg],
        ["seed spread (s.d.)"] + [fmt(a["overlap_spread"], 2) if a["overlap_runs"] and len(a["overlap_runs"]) > 1 else "-" for a in avg],
        ["average hit rate"] + [fmt(a["hit"], 2) for a in avg],
        ["AUC (success plot)"] + [fmt(a["auc"], 2) for a in avg],
        ["precision at 20 px"] + [fmt(a["precision20"], 2) for a in avg],
        ["ms per frame (mean)"] + [fmt(a["ms_mean"], 2) for a in avg],
    ]
    if delta:
        a, b = avg[ours[0]], avg[ours[1]]
        d = a["overlap"] - b["overlap"]
        spread = max(a["overlap_spread"] or 0, b["overlap_spread"] or 0)
        summary[0].append(f"{d:+.2f}" + ("*" if abs(d) > spread else ""))
        for r in summary[1:]:
            r.append("")
    widths = [max(len(str(r[i])) for r in [head] + rows + summary) for i in range(len(head))]
    line = lambda r: "  ".join(str(c).ljust(widths[0]) if i == 0 else str(c).rjust(widths[i])
                               for i, c in enumerate(r))
    first = "\n".join(group_line(entries, label, g, f, n) for g, f, n in groups if n > 0)
    if first:
        print(first)
    print("Mean overlap [%] over seeds, per sequence; averages over the sequences")
    print(line(head))
    for r in rows:
        print(line(r))
    print("-" * len(line(head)))
    for r in summary:
        print(line(r))
    if len(sys.argv) > 2:
        with open(sys.argv[2], "w") as f:
            if first:
                f.write(first + "\n\n")
            f.write("| " + " | ".join(head) + " |\n|---|" + "---:|" * (len(head) - 1) + "\n")
            for r in rows:
                f.write("| " + " | ".join(r) + " |\n")
            for r in summary:
                f.write("| **" + r[0] + "** | " + " | ".join(r[1:]) + " |\n")


if __name__ == "__main__":
    main()
