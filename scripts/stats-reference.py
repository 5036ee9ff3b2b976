"""Reference values for Kumiki's comparison statistics, computed with SciPy.

Writes tests/fixtures/stats-reference.json, which the contract's tests (crate/model/src/stats.rs)
check the Rust statistics against: the Kruskal-Wallis H test (scipy.stats.kruskal), the
Mann-Whitney U test (scipy.stats.mannwhitneyu, two-sided, with the method Kumiki uses: exact
without ties and with n1*n2 <= 10000, else the normal approximation with tie and continuity
correction), and Holm's correction, applied by hand to SciPy's p values (SciPy has no Holm).

Run once from the repository root, after `bash scripts/setup.sh --python`:
    .venv/bin/python scripts/stats-reference.py
"""

import json
import random

import scipy
from scipy import stats


def data_sets():
    rng = random.Random(40)
    sets = {
        "distinct small": [[1.5, 2.25, 3.0, 7.5], [4.0, 5.5, 6.25, 8.0, 9.0], [0.5, 10.0, 11.5]],
        "ties": [[1, 1, 2, 2, 3], [2, 3, 3, 4, 4, 4], [1, 4, 5, 5, 5, 6]],
        "shifted normal": [
            [round(rng.gauss(mu, 2.0), 3) for _ in range(25)] for mu in (10.0, 11.0, 13.0, 10.5)
        ],
        "whole-number steps": [
            [rng.randint(150, 260) for _ in range(40)] for _ in range(3)
        ],
        "two conditions, exact": [[3.1, 4.7, 5.2, 6.8, 9.9, 12.0], [1.2, 2.4, 2.9, 4.1, 5.0]],
    }
    return sets


def holm(p):
    m = len(p)
    order = sorted(range(m), key=lambda i: p[i])
    out = [0.0] * m
    floor = 0.0
    for k, i in enumerate(order):
        floor = max(floor, min(1.0, (m - k) * p[i]))
        out[i] = floor
    return out


def main():
    cases = []
    for name, groups in data_sets().items():
        groups = [[float(x) for x in g] for g in groups]
        kw = stats.kruskal(*groups)
        pairs = []
        for i in range(len(groups)):
            for j in range(i + 1, len(groups)):
                a, b = groups[i], groups[j]
                ties = len(set(a + b)) < len(a) + len(b)
                exact = not ties and len(a) * len(b) <= 10000
                r = stats.mannwhitneyu(
                    a, b, alternative="two-sided", method="exact" if exact else "asymptotic",
                    use_continuity=True,
                )
                pairs.append({"first": i, "second": j, "u": float(r.statistic), "p": float(r.pvalue),
                              "method": "exact" if exact else "normal"})
        for pair, adjusted in zip(pairs, holm([p["p"] for p in pairs])):
            pair["p_holm"] = adjusted
        cases.append({"name": name, "groups": groups,
                      "kruskal": {"h": float(kw.statistic), "p": float(kw.pvalue)},
                      "pairs": pairs})
    doc = {"made_by": "scripts/stats-reference.py", "scipy": scipy.__version__, "cases": cases}
    with open("tests/fixtures/stats-reference.json", "w") as f:
        json.dump(doc, f, indent=1)
        f.write("\n")


if __name__ == "__main__":
    main()
