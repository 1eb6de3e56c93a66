"""ns per wheel of one mf_bench result in Google Benchmark's JSON (a "benchmarks" entry): its CPU
time per iteration in ns, over the wheels one iteration evaluates (FloatFour: four, FloatBatch:
the benchmark's 1024 operating points, else one). Shared by scripts/bench-perf.sh and
scripts/bench-issue-baseline.sh."""

_NS_PER_UNIT = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}


def ns_per_wheel(run):
    per_call = run["cpu_time"] * _NS_PER_UNIT[run["time_unit"]]
    name = run["run_name"]
    if "FloatFour" in name:
        return per_call / 4
    if "FloatBatch" in name:
        return per_call / 1024  # one call evaluates the 1024 operating points
    return per_call
