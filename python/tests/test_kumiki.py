"""The Python package against the kumiki command: the same rows, hashes, exports and summaries,
and its statistics against SciPy's. The CLI is $KUMIKI_CLI, or the workspace's quick build."""

import json
import os
import subprocess
from itertools import combinations
from pathlib import Path

import pytest
from scipy import stats

import kumiki

ROOT = Path(__file__).resolve().parents[2]
CLI = os.environ.get("KUMIKI_CLI", str(ROOT / "target" / "quick" / "kumiki"))


def cli(*args, env=None):
    if not Path(CLI).exists():
        pytest.fail(f"the kumiki command is not built at {CLI}: cargo build --profile quick -p kumiki-cli")
    out = subprocess.run([CLI, *args], capture_output=True, text=True, env=env, check=True)
    return out.stdout


def lines(text):
    return [json.loads(line) for line in text.splitlines() if line.strip()]


# A Latin-hypercube sweep with a range on the grid and a stop condition in the goal language.
SAMPLED = {
    "version": 1,
    "name": "sampled",
    "scenarios": ["amas-L"],
    "grid": {"max_steps": {"start": 400, "step": 200, "end": 600}},
    "sample": {"method": "latin", "count": 3, "seed": 11,
               "ranges": {"robots": {"min": 1, "max": 6, "integer": True}}},
    "seeds": 2,
    "stop": "metrics.placed >= 15 or steps >= 300",
    "plot": {"kind": "summary", "group": ["params.robots"], "values": ["steps", "metrics.total_steps"]},
}


@pytest.fixture(scope="module")
def sampled(tmp_path_factory):
    path = tmp_path_factory.mktemp("e") / "sampled.json"
    path.write_text(json.dumps(SAMPLED))
    return path


def test_runs_give_the_rows_and_hashes_of_kumiki_run():
    df = kumiki.open("amas-L").run(seeds=3)
    assert df["hash"].tolist() == [r["hash"] for r in lines(cli("run", "amas-L", "--seeds", "3"))]
    # `kumiki run` prints each run's outcome; a row adds its parameters, scenario hash and version.
    def outcomes(df):
        return [{k: r[k] for k in ["scenario", "seed", "completed", "steps", "hash", "metrics"]} for r in df.attrs["rows"]]

    assert outcomes(df) == lines(cli("run", "amas-L", "--seeds", "3"))
    one = kumiki.open("amas-L").run(seeds=[2], set={"robots": 3}, max_steps=150)
    assert outcomes(one) == lines(cli("run", "amas-L", "--seed", "2", "--set", "robots=3", "--max-steps", "150"))
    assert one.attrs["rows"][0]["scenario_hash"] == kumiki.open("amas-L").run(seeds=[5], set={"robots": 3}, max_steps=150).attrs["rows"][0]["scenario_hash"]
    assert one["params.robots"].tolist() == [3]
    assert df.attrs["units"]["metrics.total_steps"] == "robot steps"


def test_a_scenario_opens_from_a_preset_a_dict_a_file_and_a_link(tmp_path):
    s = kumiki.open("amas-L")
    path = tmp_path / "s.json"
    path.write_text(json.dumps(s.json))
    link = cli("link", "amas-L").strip()
    hashes = {
        how: kumiki.open(src).run(seeds=[1])["hash"][0]
        for how, src in [("preset", "amas-L"), ("dict", s.json), ("file", path), ("link", link),
                         ("json text", json.dumps(s.json)), ("own link", s.link())]
    }
    assert len(set(hashes.values())) == 1, hashes
    with pytest.raises(ValueError, match="robtos: unknown field 'robtos'; did you mean 'robots'"):
        kumiki.open({**s.json, "robtos": 3})


def test_a_trace_records_any_metric_at_every_step_to_the_runs_end():
    s = kumiki.open("amas-L")
    t = s.trace(["built", "placed"], seed=1)
    row = s.run(seeds=[1]).iloc[0]
    assert t["step"].tolist() == list(range(row["steps"] + 1))
    assert t["placed"].iloc[-1] == row["metrics.placed"]
    assert t["built"].is_monotonic_increasing
    sparse = s.trace("built", seed=1, every=50)
    assert sparse["step"].tolist()[:3] == [0, 50, 100] and sparse["step"].iloc[-1] == row["steps"]
    with pytest.raises(ValueError, match="did you mean 'placed'"):
        s.trace("placd")


def test_agents_stand_on_the_lattice():
    a = kumiki.open("amas-L").agents(seed=1, every=100)
    assert len(a) > 0 and set(a["step"]) >= {0, 100}
    assert a.groupby("step")["agent"].count().max() == kumiki.open("amas-L").json["robots"]
    assert (a["x"] >= 0).all() and (a["y"] >= 0).all() and a["kind_name"].str.len().gt(0).all()


def test_a_sampled_sweep_with_a_stop_condition_gives_the_clis_rows_and_csv(sampled):
    env = {**os.environ, "SOURCE_DATE_EPOCH": "1700000000"}
    os.environ["SOURCE_DATE_EPOCH"] = "1700000000"
    try:
        e = kumiki.experiment(sampled)
        df = e.run()
    finally:
        del os.environ["SOURCE_DATE_EPOCH"]
    out = lines(cli("sweep", str(sampled), env=env))
    assert {"provenance": df.attrs["provenance"]} == out[0]
    assert df.attrs["rows"] == out[1:]
    assert len(df) == e.runs == 2 * 3 * 2
    assert (df["steps"] <= 300).all() and ((df["metrics.placed"] >= 15) | (df["steps"] == 300)).all()
    assert sorted(set(df["params.max_steps"])) == [400, 600]
    assert e.export(df, "csv") == cli("sweep", str(sampled), "--format", "csv", env=env)
    assert e.summary(df) == lines(cli("sweep", str(sampled), "--summary", env=env))


def test_three_conditions_get_kruskal_wallis_and_holm_corrected_pairs_as_scipy_computes_them(sampled):
    e = kumiki.experiment(sampled)
    df = e.run()
    summary = e.summary(df)
    groups = df.groupby("params.robots")["steps"].apply(list).to_dict()
    # The conditions in the summary's order.
    conditions = [c for c in summary if "kruskal_wallis" in c and c["value"] == "steps"][0]["conditions"]
    values = [groups[int(c.split(": ")[1])] for c in conditions]
    assert len(values) == 3
    kw = [c for c in summary if "kruskal_wallis" in c and c["value"] == "steps"][0]["kruskal_wallis"]
    ref = stats.kruskal(*values)
    assert kw["h"] == pytest.approx(ref.statistic, rel=1e-9)
    assert kw["p"] == pytest.approx(ref.pvalue, rel=1e-9)
    pairs = [c for c in summary if "comparison" in c and c["value"] == "steps"]
    assert [tuple(p["conditions"]) for p in pairs] == list(combinations(conditions, 2))
    ps = []
    for p, (i, j) in zip(pairs, combinations(range(3), 2)):
        a, b = values[i], values[j]
        assert p["direction"] == "first minus second"
        assert p["comparison"]["difference"] == pytest.approx(sum(a) / len(a) - sum(b) / len(b))
        method = "exact" if p["comparison"]["method"] == "exact" else "asymptotic"
        ref = stats.mannwhitneyu(a, b, alternative="two-sided", method=method)
        assert p["comparison"]["u"] == ref.statistic
        assert p["comparison"]["p"] == pytest.approx(ref.pvalue, rel=1e-9)
        ps.append(ref.pvalue)
    # Holm: the k-th smallest p times (m - k + 1), never below the one before, at most 1.
    order = sorted(range(3), key=lambda k: ps[k])
    floor, holm = 0.0, [0.0] * 3
    for k, i in enumerate(order):
        floor = max(floor, min(1.0, (3 - k) * ps[i]))
        holm[i] = floor
    assert [p["p_holm"] for p in pairs] == pytest.approx(holm, rel=1e-9)


def test_a_part_of_a_sweep_is_marked_partial_with_only_its_seeds(sampled):
    e = kumiki.experiment(sampled)
    df = e.run()
    part = df[df["seed"] == 2]
    csv = e.export(part, "csv", time="2024-01-01T00:00:00Z")
    assert f"# partial: {len(part)} of {e.runs} runs" in csv
    assert "# seeds: 2\n" in csv
    assert e.summary(part)[-1]["partial"] == {"runs": len(part), "of": e.runs}
    assert "partial: 6 of 12 runs" in e.svg(part)


def test_figures_are_the_clis_svg_and_a_pdf(sampled, tmp_path):
    e = kumiki.experiment("chobie-load")
    df = e.run()
    cli("sweep", "chobie-load", "--plot", "svg", "--plot-dir", str(tmp_path))
    for i in range(len(e.figures(df))):
        assert e.svg(df, i) == (tmp_path / f"chobie-load-{i + 1}.svg").read_text()
        pdf = e.pdf(df, i)
        assert pdf.startswith(b"%PDF-1.4") and pdf.rstrip().endswith(b"%%EOF")
    assert kumiki.format_number(165.25) == "165.3" and kumiki.format_number(9825.5) == "9,825.5"


def test_hand_ins_are_graded_as_kumiki_check_grades_them():
    lesson = kumiki.open("lesson-amas-robots")
    handin = {**lesson.json, "robots": 3}
    graded = kumiki.check([handin, "not a link"], exercise="lesson-amas-robots")
    ref = lines(cli("check", lesson.with_(robots=3).link(), "--exercise", "lesson-amas-robots", "--format", "json"))[0]
    row = graded.iloc[0]
    assert (row["met"], row["steps"], row["hash"]) == (ref["met"], ref["steps"], ref["hash"])
    assert row["changed"] == ref["changed"]
    assert graded.iloc[1]["error"].startswith("'not a link' is not")


def test_lists_and_metrics():
    assert "amas-L" in kumiki.presets() and "chobie-load" in kumiki.experiments()
    assert "lesson-amas-robots" in kumiki.lessons()
    m = kumiki.metrics("amas")
    assert "total_steps" in set(m["name"]) and set(m.columns) == {"model", "name", "unit", "about"}
