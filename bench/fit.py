"""Convergence figures from (time, error) runs: slope, efficiency, time to an error.

Monte Carlo error (MSE) falls as 1 / time once an estimator is in its
asymptotic regime, a slope of -1 in log-log; a biased estimator's error
flattens out at its bias instead.
"""

import math


def fit_slope(times, errors):
    """Least-squares line through (log10 time, log10 error): (slope, intercept).

    Runs with a non-positive time or error carry no logarithm and are left
    out; fewer than two remaining runs give None.
    """
    points = [(math.log10(t), math.log10(e)) for t, e in zip(times, errors) if t > 0 and e > 0]
    if len(points) < 2:
        return None
    mx = sum(x for x, _ in points) / len(points)
    my = sum(y for _, y in points) / len(points)
    sxx = sum((x - mx) ** 2 for x, _ in points)
    if sxx == 0:
        return None
    slope = sum((x - mx) * (y - my) for x, y in points) / sxx
    return slope, my - slope * mx


def efficiency(error, seconds):
    """1 / (error x time): constant for an estimator in its asymptotic regime, higher is better."""
    return 1.0 / (error * seconds) if error > 0 and seconds > 0 else math.nan


# Extrapolating past the last run trusts the trend of the last runs only if
# it falls at least this fast; flatter, the error is taken to have stalled.
MIN_EXTRAPOLATION_SLOPE = -0.5
TAIL_RUNS = 3


def time_to_reach(times, errors, target):
    """Seconds until the error falls to `target`, as (seconds, extrapolated) or None.

    Runs are taken in order of time. Where a run reaches the target, the
    time is interpolated in log-log between it and the run before; where no
    run does, it is extrapolated along the line fitted to the last runs,
    provided that line falls at least as fast as MIN_EXTRAPOLATION_SLOPE.
    """
    runs = sorted((t, e) for t, e in zip(times, errors) if t > 0 and e > 0)
    for i, (t, e) in enumerate(runs):
        if e <= target:
            if i == 0:
                return t, False
            (t0, e0) = runs[i - 1]
            f = (math.log(target) - math.log(e0)) / (math.log(e) - math.log(e0))
            return math.exp(math.log(t0) + f * (math.log(t) - math.log(t0))), False
    tail = runs[-TAIL_RUNS:]
    fit = fit_slope([t for t, _ in tail], [e for _, e in tail])
    if fit is None or fit[0] > MIN_EXTRAPOLATION_SLOPE:
        return None
    slope, intercept = fit
    return 10 ** ((math.log10(target) - intercept) / slope), True
