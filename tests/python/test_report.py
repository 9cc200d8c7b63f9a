"""test_report.py — known-answer tests of python/canopyfoam/report.py and bin/canopy-report on synthetic canopy.dat files.

Run as:  /usr/bin/python3 tests/python/test_report.py   (./Alltest report)
Prints one PASS/FAIL line per check with the numbers; exits 1 if any fails.

The synthetic run (dt = 0.01 s, 0 .. 12 s, gravity (0 0 -9.81)):
  descent speed  V(t) = Vt (1 - exp(-t/tau)) + aV sin(2 pi fV t + phiV)
                 Vt = 4 m/s, tau = 0.5 s, aV = 0.05 m/s, fV = 2 Hz
  diameter       D(t) = Dinf (1 - 0.3 exp(-t/tau)) + aD sin(2 pi f t + phiD)
                 Dinf = 1.5 m, aD = 0.04 m, f = 2 Hz
  force          F_z = 0.9 W (1 + 0.02 sin(2 pi fV t)), W = 6.02 kg * 9.81
  iterations     3, 4, 5, 6, 3, 4, ... (mean 4.5)
  swing          U_x = aH sin(2 pi fH t), aH = 0.3 m/s, fH = 0.25 Hz
written as a run restarted twice, in folders 0 (to t = 13), 4 (4.01 .. 10.5)
and 10 (10.01 .. 12): rows 4.01 .. 13 of folder 0 and 10.01 .. 10.5 of
folder 4 hold wrong values (V + 100, 100 iterations) that the later folders
must override (all of them: the series ends at 12 s with the last
restart); "10" sorts before "4" as a string, so a lexical order fails.
Folder 10 is in the solver's later layout (a title comment, 3 frame
columns more, found by the column-name line) and ends with a line cut
short, as a crash leaves it.

Steady interval (default, last 1/3): t = 8 .. 12 s, 401 samples. There
fV t spans whole periods, so the exact time averages are
  mean V = Vt - Vt tau (exp(-8/tau) - exp(-12/tau)) / 4  (= 4 - 5.6e-8)
  std V  = aV / sqrt(2)        (the exponential adds ~1e-7 relative)
and the trapezoidal rule on 50 samples per period is exact for them, so
1e-6 m/s is a tolerance with margin that still catches an unweighted
sample mean (the phase phiV makes its end-point bias ~8e-5 m/s).
"""

import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(ROOT, "python"))

from canopyfoam import report  # noqa: E402

failures = []

# The synthetic run's constants
DT = 0.01
VT, TAU, AV, FV, PHIV = 4.0, 0.5, 0.05, 2.0, 0.7
DINF, AD, F_BREATH, PHID = 1.5, 0.04, 2.0, 0.3
D0, MASS, RHO, G = 2.134, 6.02, 1.2, 9.81
FORCE_SHARE = 0.9
AH, FH = 0.3, 0.25               # swing: horizontal payload velocity along x


def check(name, ok, detail):
    print("%s %s: %s" % ("PASS" if ok else "FAIL", name, detail))
    if not ok:
        failures.append(name)
    return ok


def close(name, got, want, tol, unit=""):
    """|got - want| <= tol, printed with the numbers."""
    ok = got is not None and abs(got - want) <= tol
    err = float("nan") if got is None else got - want
    return check(name, ok, "got %s, expected %.10g, error %.3g (tolerance "
                 "%.3g)%s" % ("None" if got is None else "%.10g" % got, want,
                              err, tol, " " + unit if unit else ""))


def row(t, ghat, f_breath=F_BREATH, corrupt=False, step=0, frame=False):
    """One canopy.dat row of the synthetic run at time t."""
    V = VT * (1 - math.exp(-t / TAU)) + AV * math.sin(2 * math.pi * FV * t
                                                        + PHIV)
    D = DINF * (1 - 0.3 * math.exp(-t / TAU)) + AD * math.sin(
        2 * math.pi * f_breath * t + PHID)
    drag = FORCE_SHARE * MASS * G * (1 + 0.02 * math.sin(2 * math.pi * FV * t))
    iterations = 3 + step % 4
    if corrupt:
        V += 100.0
        iterations = 100
    v = [V * c for c in ghat]                 # velocity along gravity
    v[0] += AH * math.sin(2 * math.pi * FH * t)   # across it (ghat.x = 0)
    x = [-0.5 * V * t * c for c in ghat]      # not analysed
    force = [-drag * c for c in ghat]         # against gravity
    values = ([t] + x + v + force
              + [D, 0.8 * D * D, 0.5 * MASS * V * V, 1.0, -MASS * G * x[2],
                 iterations, 1e-4, 0.01, 12]
              + ([0.1 * t, -7.0, 1e3] if frame else []))
    return " ".join("%.17g" % value for value in values)


COLUMN_LINE = ("# time payload_x payload_y payload_z payload_Ux payload_Uy"
               " payload_Uz force_x force_y force_z projected_diameter"
               " canopy_area kinetic spring gravity coupling_iterations"
               " residual slip substeps")


def write_dat(path, header, times, ghat, f_breath=F_BREATH, corrupt_from=None,
              tail="", frame=False, columns=COLUMN_LINE):
    """frame: the solver's later layout, 3 more columns frame_x/y/z."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        for line in header:
            f.write(line + "\n")
        f.write(columns + (" frame_x frame_y frame_z" if frame else "")
                + "\n")
        for step, t in times:
            bad = corrupt_from is not None and t > corrupt_from + 1e-9
            f.write(row(t, ghat, f_breath, bad, step, frame) + "\n")
        f.write(tail)


def steps(first, last):
    """(step index, time) for steps first..last of size DT."""
    return [(n, n * DT) for n in range(first, last + 1)]


HEADER = ["# nominalDiameter %g" % D0, "# totalMass %g" % MASS,
          "# rho %g" % RHO, "# gravity 0 0 %g" % -G]
DOWN = (0.0, 0.0, -1.0)


def make_restarted_case(case):
    base = os.path.join(case, "postProcessing", "canopy")
    # folder 0: steps 1..1300 (t = 0.01 .. 13, beyond the restarts' end);
    # rows after t = 4 are wrong
    write_dat(os.path.join(base, "0", "canopy.dat"), HEADER, steps(1, 1300),
              DOWN, corrupt_from=4.0)
    # folder 4: restart from 4, steps 401..1050; rows after t = 10 are wrong
    write_dat(os.path.join(base, "4", "canopy.dat"), HEADER,
              steps(401, 1050), DOWN, corrupt_from=10.0)
    # folder 10: restart from 10, steps 1001..1200, then a line cut short;
    # written as the solver now does: a title line, 3 frame columns more
    write_dat(os.path.join(base, "10", "canopy.dat"),
              ["# canopyFoam time series of the canopy (ground frame)"]
              + HEADER, steps(1001, 1200), DOWN, tail="12.01 0 0 -4.0",
              frame=True)


def test_restarts_and_statistics(tmp):
    case = os.path.join(tmp, "restarted")
    make_restarted_case(case)
    r = report.analyse(case)
    series = r["_series"]
    t = series.t

    # Concatenation of the restarts
    check("restart order", [f["startTime"] for f in r["files"]] == [0, 4, 10],
          "folders taken in the order %s (expected 0, 4, 10)"
          % [f["startTime"] for f in r["files"]])
    check("restart steps", r["steps"] == 1200 and
          abs(t[0] - 0.01) < 1e-12 and abs(t[-1] - 12.0) < 1e-12,
          "%d steps, t = %.10g .. %.10g (expected 1200, 0.01 .. 12)"
          % (r["steps"], t[0], t[-1]))
    dt = [b - a for a, b in zip(t[:-1], t[1:])]
    check("restart time axis", max(abs(d - DT) for d in dt) < 1e-9,
          "steps between %.12g and %.12g s (expected all %.2g)"
          % (min(dt), max(dt), DT))
    check("restart overrides", r["overriddenRows"] == 950 and
          [f["used"] for f in r["files"]] == [400, 600, 200],
          "%d rows overridden (expected 900 + 50), rows used per folder %s "
          "(expected [400, 600, 200])"
          % (r["overriddenRows"], [f["used"] for f in r["files"]]))
    vmax = float(max(r["_descent"]))
    check("restart wrong rows gone", vmax < VT + AV + 1e-9,
          "largest descent speed %.6g m/s (the overridden rows hold > 100)"
          % vmax)
    check("restart truncated line", r["skippedLines"] == 1,
          "%d bad line(s) skipped (expected the 1 cut short)"
          % r["skippedLines"])

    # The swing across gravity: one full period (4 s) in 8 .. 12, so the
    # mean of |AH sin| is 2 AH / pi (trapezoid weights on 401 samples:
    # ~1e-5 relative); the peaks at t = 9, 11 s are samples
    h = r["horizontalVelocity"]
    close("horizontal speed mean", h["mean"], 2 * AH / math.pi, 1e-4, "m/s")
    close("horizontal speed max", h["max"], AH, 1e-12, "m/s")

    # The steady interval: last third of 0 .. 12
    s = r["steady"]
    check("steady interval", abs(s["start"] - 8.0) < 1e-9 and
          abs(s["end"] - 12.0) < 1e-9 and s["samples"] == 401,
          "t = %.10g .. %.10g, %d samples (expected 8 .. 12, 401)"
          % (s["start"], s["end"], s["samples"]))

    # Terminal velocity, spread, extremes
    v = r["descentVelocity"]
    mean_exact = VT - VT * TAU * (math.exp(-8 / TAU) - math.exp(-12 / TAU)) / 4
    close("terminal velocity mean", v["mean"], mean_exact, 1e-6, "m/s")
    close("terminal velocity std", v["std"], AV / math.sqrt(2), 1e-6, "m/s")
    # sampled extremes of the sine miss the true ones by at most
    # aV (1 - cos(pi fV dt)) (half a step from the crest)
    crest = AV * (1 - math.cos(math.pi * FV * DT)) + 1e-9
    close("terminal velocity max", v["max"], VT + AV, crest, "m/s")
    close("terminal velocity min", v["min"], VT - AV, crest, "m/s")
    # drift = least-squares slope x interval length; the sine's slope over
    # whole periods is -12 aV cos(w t1 + phi) / (w T^2) for continuous data
    # (-9.1e-3 m/s here); the 401 samples give it to O(1/N): recomputed
    # from the sums, to round-off.
    ts = [x for x in t if x >= 8.0 - 1e-9]
    ys = list(r["_descent"][-len(ts):])
    tm, ym = sum(ts) / len(ts), sum(ys) / len(ys)
    slope = (sum((a - tm) * (b - ym) for a, b in zip(ts, ys))
             / sum((a - tm) ** 2 for a in ts))
    w = 2 * math.pi * FV
    continuous = -12 * AV * math.cos(w * 12 + PHIV) / (w * 4.0)
    close("terminal velocity drift (continuous %.4g)" % continuous,
          v["drift"], slope * 4.0, 1e-9, "m/s")
    check("steady (no warning)", not s["warning"], repr(s["warning"]))

    # Breathing at 2 Hz: N = 401, N dt = 4.01 s, df = 0.2494 Hz;
    # 2 Hz is 8.02 bins, so the peak bin is 8 and its centre within df/2.
    b = r["breathing"]
    df = b["resolution"]
    close("breathing resolution", df, 1 / (401 * DT), 1e-12, "Hz")
    check("breathing resolved", b["resolved"] and b["peakBin"] == 8,
          "resolved %s, peak bin %s (expected True, 8)"
          % (b["resolved"], b["peakBin"]))
    close("breathing peak bin within df/2", b["binFrequency"], F_BREATH,
          df / 2, "Hz")
    # The Hann ratio refinement is exact for one complex tone; what is left
    # is the leakage of the tone's image at -f (~(2k)^-3 = 2e-4 of the peak
    # at k = 8) and of the detrended tail: 0.02 df bounds it with margin.
    close("breathing refined frequency", b["frequency"], F_BREATH, 0.02 * df,
          "Hz")
    # amplitude: the Hann scaling shows aD for a tone on a bin; 0.02 bins
    # off it loses (1 - sinc-type factor) < 0.2 %, the image adds < 0.1 %
    close("breathing amplitude", b["amplitude"], AD, 0.01 * AD, "m")
    # The descent speed's spectrum in the breathing's band (from St 0.1,
    # f_min = 0.1 V / Dp = 0.27 Hz): its 2 Hz tone of aV, the same bin and
    # the same bounds as the diameter's; St = fV Dp / V with Dp the mean
    # projected diameter
    vb = r["descentBand"]
    close("descent band refined frequency", vb["frequency"], FV, 0.02 * df,
          "Hz")
    close("descent band amplitude", vb["amplitude"], AV, 0.01 * AV, "m/s")
    close("descent band Strouhal number", vb["strouhal"],
          vb["frequency"] * r["projectedDiameter"]["mean"]
          / r["descentVelocity"]["mean"], 1e-12)

    # Drag coefficients, by hand: W = 6.02 * 9.81 = 59.0562 N,
    # S0 = pi 2.134^2 / 4 = 3.576669 m^2, q = 0.6 * 4^2 = 9.6 Pa,
    # C_D = 59.0562 / (9.6 * 3.576669) = 1.719949; the pressure force
    # carries 0.9 W: C_D = 1.547954. (V differs from 4 by 1.4e-8 relative.)
    cd = r["dragCoefficient"]
    close("C_D weight balance", cd["weightBalance"], 1.719949, 2e-6)
    close("C_D pressure force", cd["pressureForce"], 1.547954, 2e-6)
    close("weight", cd["weight"], 59.0562, 1e-9, "N")
    close("nominal area", cd["nominalArea"], 3.5766687, 1e-7, "m^2")

    # Coupling iterations 3,4,5,6,... over 1200 steps (the wrong rows say 100)
    c = r["coupling"]
    close("mean coupling iterations", c["meanIterations"], 4.5, 1e-12)
    return case, r


def test_half_bin_and_direction(tmp):
    """Breathing half-way between two bins, gravity along -y."""
    case = os.path.join(tmp, "halfbin")
    f_half = 8.5 / (401 * DT)      # 8.5 bins of the 401-sample interval
    header = ["# nominalDiameter %g" % D0, "# totalMass %g" % MASS,
              "# rho %g" % RHO, "# gravity 0 %g 0" % -G]
    write_dat(os.path.join(case, "postProcessing", "canopy", "0",
                           "canopy.dat"), header, steps(1, 1200),
              (0.0, -1.0, 0.0), f_breath=f_half)
    r = report.analyse(case)
    b = r["breathing"]
    df = b["resolution"]
    close("half-bin peak bin within df/2", b["binFrequency"], f_half,
          df / 2 + 1e-12, "Hz")
    close("half-bin refined frequency", b["frequency"], f_half, 0.02 * df,
          "Hz")
    mean_exact = VT - VT * TAU * (math.exp(-8 / TAU) - math.exp(-12 / TAU)) / 4
    close("gravity along -y: descent speed", r["descentVelocity"]["mean"],
          mean_exact, 1e-6, "m/s")
    close("gravity along -y: C_D pressure force",
          r["dragCoefficient"]["pressureForce"], 1.547954, 2e-6)


def test_breathing_band():
    """A slow swing (0.1 Hz, 0.2 m) over a small breathing (0.9 Hz, 0.02 m),
    0 .. 40 s at 0.01 s: the whole spectrum's peak is the swing, the band
    from 0.3 Hz finds the breathing (both tones on whole bins of the 40 s
    window: the Hann formula is exact for a lone tone there, and the other
    tone's leakage moves it by less than 1e-3 Hz, 0.04 bins); a band that
    starts on the swing's falling flank finds no peak; and breathing_band's
    Strouhal number is f Dp / V."""
    n = 4001
    t = [DT * i for i in range(n)]
    y = [1.5 + 0.2 * math.sin(2 * math.pi * 0.1 * x)
         + 0.02 * math.sin(2 * math.pi * 0.9 * x) for x in t]
    whole = report.breathing(t, y)
    close("whole spectrum: the slow swing", whole["frequency"], 0.1, 1e-3,
          "Hz")
    band = report.breathing(t, y, 0.3)
    close("band from 0.3 Hz: the breathing", band["frequency"], 0.9, 1e-3,
          "Hz")
    close("band from 0.3 Hz: its amplitude", band["amplitude"], 0.02, 1e-3,
          "m")
    flank = report.breathing(t, [1.5 + 0.2 * math.sin(2 * math.pi * 0.1 * x)
                                 for x in t], 0.125)
    check("a band on the swing's flank: no peak", not flank["resolved"]
          and "falls across the band" in flank["note"],
          "resolved %s, note '%s'" % (flank["resolved"], flank["note"]))
    tail = report.breathing(t, y, 0.125)
    close("band from the swing's flank: the breathing, not the flank",
          tail["frequency"], 0.9, 1e-3, "Hz")
    bb = report.breathing_band(t, y, 4.0, 1.5)
    close("breathing_band: f_min = 0.1 V / Dp", bb["fMin"], 0.1 * 4.0 / 1.5,
          1e-12, "Hz")
    close("breathing_band: St = f Dp / V", bb["strouhal"], 0.9 * 1.5 / 4.0,
          1e-3 * 1.5 / 4.0)
    check("breathing_band: none without descent",
          report.breathing_band(t, y, 0.0, 1.5) is None, "speed 0")
    flat = report.breathing_band(t, [5.0] * n, 4.0, 1.5, "the descent speed")
    check("a steady series: its name in the note", not flat["resolved"]
          and flat["note"] == "no oscillation of the descent speed",
          "resolved %s, note '%s'" % (flat["resolved"], flat["note"]))


def test_not_resolved(tmp):
    """0 .. 1.2 s: the last third holds 0.8 breathing periods."""
    case = os.path.join(tmp, "short")
    write_dat(os.path.join(case, "postProcessing", "canopy", "0",
                           "canopy.dat"), HEADER, steps(1, 120), DOWN)
    r = report.analyse(case)
    b = r["breathing"]
    check("short run: breathing not resolved",
          not b["resolved"] and b["frequency"] is None
          and "not resolved" in report.format_summary(r),
          "resolved %s, peak bin %s, resolution %.3g Hz, note '%s'"
          % (b["resolved"], b["peakBin"], b["resolution"], b["note"]))


def test_missing_quantities(tmp):
    case = os.path.join(tmp, "missing")
    write_dat(os.path.join(case, "postProcessing", "canopy", "0",
                           "canopy.dat"),
              ["# rho %g" % RHO, "# gravity 0 0 %g" % -G], steps(1, 300),
              DOWN)
    try:
        report.analyse(case)
        check("missing quantities raise", False, "no error raised")
    except report.MissingQuantityError as e:
        text = str(e)
        check("missing quantities raise",
              e.missing == ["nominalDiameter", "totalMass"]
              and "nominal diameter" in text and "--diameter" in text
              and "total mass" in text and "--mass" in text
              and "rho" not in e.missing,
              "missing %s; message: %s" % (e.missing, text.replace("\n",
                                                                   " | ")))
    # a column-name line without a column the analysis needs
    bad = os.path.join(tmp, "badcolumns")
    write_dat(os.path.join(bad, "postProcessing", "canopy", "0",
                           "canopy.dat"), HEADER, steps(1, 30), DOWN,
              columns=COLUMN_LINE.replace("projected_diameter",
                                          "diameter"))
    try:
        report.analyse(bad)
        check("missing column raises", False, "no error raised")
    except report.ReportError as e:
        check("missing column raises", "projected_diameter" in str(e),
              str(e))
    # the command line names them too, and exits 1
    tool = os.path.join(ROOT, "bin", "canopy-report")
    p = subprocess.run([tool, case, "--no-plots"], stdout=subprocess.PIPE,
                       stderr=subprocess.PIPE, universal_newlines=True)
    check("missing quantities: canopy-report exits 1",
          p.returncode == 1 and "nominal diameter" in p.stderr
          and "--mass" in p.stderr,
          "exit %d, stderr: %s" % (p.returncode, p.stderr.strip()
                                   .replace("\n", " | ")))
    # options fill in and override: --rho 1.0 instead of the header's 1.2
    r = report.analyse(case, diameter=D0, mass=MASS, rho=1.0)
    p = r["parameters"]
    check("options fill in and override the header",
          p["nominalDiameter"]["source"] == "--diameter"
          and p["rho"]["value"] == 1.0 and p["rho"]["source"] == "--rho"
          and p["gravity"]["source"] == "canopy.dat header",
          "sources: %s" % {k: (v["value"], v["source"]) for k, v in p.items()})


def test_command_line(tmp, case, expected):
    """bin/canopy-report on the restarted case: files, stdout, JSON."""
    tool = os.path.join(ROOT, "bin", "canopy-report")
    out = os.path.join(tmp, "out")
    p = subprocess.run([tool, case, "--out", out, "--reference", "7ft"],
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True)
    print("---- canopy-report output ----\n" + p.stdout + p.stderr
          + "------------------------------")
    check("canopy-report exits 0", p.returncode == 0,
          "exit %d" % p.returncode)
    names = ["descentVelocity.png", "projectedDiameter.png", "summary.txt",
             "report.json"]
    sizes = {n: (os.path.getsize(os.path.join(out, n))
                 if os.path.isfile(os.path.join(out, n)) else 0)
             for n in names}
    check("canopy-report files", all(v > 0 for v in sizes.values()),
          "sizes %s" % sizes)
    for n in names[:2]:
        path = os.path.join(out, n)
        with open(path, "rb") as f:
            check("%s is a PNG" % n, f.read(8) == b"\x89PNG\r\n\x1a\n",
                  "%d bytes" % sizes[n])
    if sizes["summary.txt"]:
        with open(os.path.join(out, "summary.txt")) as f:
            summary = f.read()
        check("summary.txt = stdout", summary == p.stdout,
              "%d lines" % summary.count("\n"))
        check("summary names the interval and reference",
              "t = 8 .. 12 s" in summary and "4.27" in summary
              and "last 1/3" in summary, "")
    if sizes["report.json"]:
        with open(os.path.join(out, "report.json")) as f:
            data = json.load(f)
        close("report.json terminal velocity",
              data["descentVelocity"]["mean"],
              expected["descentVelocity"]["mean"], 1e-12, "m/s")
        close("report.json breathing", data["breathing"]["frequency"],
              expected["breathing"]["frequency"], 1e-12, "Hz")
    # --steady-start 6: 601 samples; V mean still Vt within the tail
    r = report.analyse(case, steady_start=6.0)
    s = r["steady"]
    check("--steady-start", abs(s["start"] - 6) < 1e-9 and s["samples"] == 601,
          "t = %.10g .. %.10g, %d samples (expected 6 .. 12, 601)"
          % (s["start"], s["end"], s["samples"]))
    mean_exact = VT - VT * TAU * (math.exp(-6 / TAU) - math.exp(-12 / TAU)) / 6
    close("--steady-start terminal velocity", r["descentVelocity"]["mean"],
          mean_exact, 1e-6, "m/s")
    # --steady-start 6 --steady-end 9: 301 samples, the exact mean over them
    r = report.analyse(case, steady_start=6.0, steady_end=9.0)
    s = r["steady"]
    check("--steady-end", abs(s["start"] - 6) < 1e-9 and abs(s["end"] - 9)
          < 1e-9 and s["samples"] == 301,
          "t = %.10g .. %.10g, %d samples (expected 6 .. 9, 301)"
          % (s["start"], s["end"], s["samples"]))
    mean_exact = VT - VT * TAU * (math.exp(-6 / TAU) - math.exp(-9 / TAU)) / 3
    close("--steady-end terminal velocity", r["descentVelocity"]["mean"],
          mean_exact, 1e-6, "m/s")
    try:
        report.analyse(case, steady_start=6.0, steady_end=5.0)
        check("--steady-end before --steady-start is refused", False, "")
    except report.ReportError as e:
        check("--steady-end before --steady-start is refused",
              "--steady-end" in str(e), str(e))


def test_references(tmp, case):
    """Every published reference: summary and plot work with the values it
    has (each optional); the tutorials' ones say what the seed states."""
    keys = {"descentVelocityDropTest", "descentVelocitySimulation",
            "descentVelocitySimulationRange", "breathingFrequencyDropTest",
            "breathingFrequencySimulation", "breathingPeriodExperiment",
            "breathingPeriodSimulation"}
    for name, ref in sorted(report.REFERENCES.items()):
        check("reference %s has a title, D0 and a value" % name,
              "title" in ref and ref.get("nominalDiameter", 0) > 0
              and bool(keys & set(ref)), "keys %s" % sorted(ref))
    r = report.analyse(case, reference="T10")
    summary = report.format_summary(r)
    check("T10 reference: payload range and periods in the summary",
          "seed simulation 3-6 m/s for payloads 100-600 kg" in summary
          and "experiment period 2.3 s (0.435 Hz)" in summary
          and "seed simulation period about 2 s (0.5 Hz)" in summary
          and "the reference is for D0 = 10.7 m" in summary,
          summary.replace("\n", " | "))
    out = os.path.join(tmp, "out-T10")
    os.makedirs(out)
    paths = report.plot(r, out)
    check("T10 reference: plots", all(os.path.getsize(x) > 0 for x in paths),
          ", ".join(os.path.basename(x) for x in paths))
    r = report.analyse(case, reference="G11third")
    summary = report.format_summary(r)
    # V = 4 m/s against the seed's 3 m/s: V/ref = 1.333
    check("G11third reference: terminal velocity without drop test",
          "seed simulation 3 m/s (V/ref = 1.333)" in summary
          and "drop test" not in summary,
          summary.replace("\n", " | "))
    r = report.analyse(case, reference="C9")
    summary = report.format_summary(r)
    check("C9 reference: breathing period only",
          "seed simulation period about 2 s (0.5 Hz)" in summary
          and "V/ref" not in summary, summary.replace("\n", " | "))
    r = report.analyse(case, reference="7ft")
    summary = report.format_summary(r)
    check("7ft reference lines unchanged",
          "drop test 4.27 m/s (V/ref = 0.937), seed simulation 3.9 +- 0.05 "
          "m/s" in summary and "drop test about 2 Hz, seed simulation "
          "1.6-2 Hz" in summary, summary.replace("\n", " | "))


def run_checks(tmp, body, what):
    """Run body() (the checks), count an unexpected error as a failure, and
    print the verdict; tmp is removed when everything passed. Returns the
    exit status."""
    try:
        body()
    except Exception as e:  # an unexpected error is a failure too
        import traceback
        traceback.print_exc()
        failures.append("exception: %s" % e)
    if failures:
        print("FAIL: %d check(s) failed: %s; files kept in %s"
              % (len(failures), ", ".join(failures), tmp))
        return 1
    shutil.rmtree(tmp, ignore_errors=True)
    print("PASS: all %s checks" % what)
    return 0


def test_mean_confidence(tmp):
    """The mean's 95 % interval from the series' autocorrelation, on 400
    independent AR(1) series y_k = phi y_{k-1} + e_k (phi 0.9, 4000
    steps of 0.01 s, seeded): the true mean 0 must lie inside the
    interval of about 95 % of them. With phi 0.9 the integral time is
    ~0.095 s, so the raw std over sqrt(N) would be ~4 times too narrow
    and cover only ~40 %. The binomial spread of the count over 400 is
    1.1 %; the tolerance [0.90, 0.99] also holds the estimator's bias
    (the autocorrelation summed to its first zero)."""
    import numpy as np
    rng = np.random.default_rng(20261124)
    phi, n, dt, trials = 0.9, 4000, 0.01, 400
    t = dt * np.arange(n)
    inside = naive_inside = 0
    t_ints = []
    for _ in range(trials):
        e = rng.standard_normal(n)
        y = np.empty(n)
        y[0] = e[0] / math.sqrt(1 - phi * phi)
        for k in range(1, n):
            y[k] = phi * y[k - 1] + e[k]
        ci, t_int, _ = report.mean_confidence(t, y)
        inside += abs(y.mean()) <= ci
        naive_inside += abs(y.mean()) <= 1.96 * y.std() / math.sqrt(n)
        t_ints.append(t_int)
    coverage = inside / trials
    check("the 95 % interval holds the true mean of ~95 % of AR(1) series",
          0.90 <= coverage <= 0.99,
          "%.3f of %d (the raw std's interval: %.3f)"
          % (coverage, trials, naive_inside / trials))
    want = dt * (0.5 + phi / (1 - phi))
    close("integral time of the AR(1) series (mean over the trials)",
          float(np.mean(t_ints)), want, 0.15 * want, "s")
    # A drift (a ramp: the descent still speeding up) is one long
    # correlated excursion: ~3 independent samples, an interval as wide
    # as the spread itself (the raw std over sqrt(N) would be 15 times
    # narrower over these 200 points)
    ramp = t[:200]
    ci, _, n_eff = report.mean_confidence(ramp, ramp)
    check("a drift's interval is as wide as its spread",
          n_eff < 4 and ci >= 0.9 * ramp.std(),
          "half-width %.3g, std %.3g, %.2g independent samples"
          % (ci, ramp.std(), n_eff))


def test_swing(tmp):
    """The suspension's swing from the canopy's centre and the payload:
    theta(t) = 10 deg sin(2 pi 0.25 t) in the x-z plane, lines of 2.5 m,
    12 s at 0.01 s, gravity -z. Expected: largest angle 10 deg (the
    samples hit the crest to 1e-4), rms 10/sqrt(2) deg (whole periods:
    exact to 1e-3), period 4 s and the x offset's fundamental
    2 L J1(theta0) = 0.4347 m (J1 the Bessel function) from the detrended,
    Hann-windowed spectrum of 12.01 s: the tone sits 0.1 % off its bin and
    its third harmonic leaks into it, which the single-tone refinement and
    the on-bin amplitude do not undo (measured: 0.34 % in period, 0.8 % in
    amplitude), so 0.5 % and 1.5 %; a wrong bin is off by 8 %. An older
    canopy.dat without the centre gives no swing."""
    import numpy as np
    t = np.arange(0, 12.0 + 1e-9, 0.01)
    theta0, length = math.radians(10.0), 2.5
    theta = theta0 * np.sin(2 * math.pi * 0.25 * t)
    offset = np.stack([length * np.sin(theta), 0 * t,
                       length * np.cos(theta)], axis=1)
    sw = report.suspension_swing(t, offset, np.array([0.0, 0.0, -1.0]))
    close("swing: largest angle", sw["angleMax"], 10.0, 1e-4, "deg")
    close("swing: rms angle", sw["angleRms"], 10.0 / math.sqrt(2), 1e-3,
          "deg")
    close("swing: period", sw["period"], 4.0, 0.02, "s")
    j1 = sum((-1) ** k * (theta0 / 2) ** (2 * k + 1)
             / (math.factorial(k) * math.factorial(k + 1)) for k in range(8))
    close("swing: amplitude of the offset's fundamental", sw["amplitude"],
          2 * length * j1, 0.015 * 2 * length * j1, "m")
    # |theta| has its kinks on samples (t = 0, 2, 4 ... s), where the
    # trapezoidal rule's error is of order h^2: measured 1.3e-4 deg
    close("swing: mean angle (2/pi of the amplitude)", sw["angleMean"],
          20.0 / math.pi, 1e-3, "deg")
    # 10 deg sin(pi t / 2) passes 5 deg at t = 1/3 s: the first sample
    # beyond it is 0.34 s
    close("swing: first time beyond 5 deg",
          report.swing_onset(t, np.degrees(theta)), 0.34, 1e-9, "s")
    nan = np.full_like(offset, np.nan)
    check("no swing without the canopy's centre",
          report.suspension_swing(t, nan, np.array([0.0, 0.0, -1.0]))
          is None, "None")


def test_departure_and_glide():
    """The glide: the payload moving at 1.5 m/s along x and 5 m/s down,
    with a swing of 0.4 m/s amplitude along y over whole periods (12 s at
    0.25 Hz): the mean velocity across gravity is 1.5 m/s along x (the
    swing averages out; trapezoidal rule exact for whole periods, so
    1e-9) at atan(1.5/5) = 16.699 deg. The departure: H = 1e-4 exp(0.9 t)
    m/s at a steady 5 m/s descent: the fit over H/V from 0.01 to 0.2 is
    exact for a pure exponential (1e-9 of the rate), its window from the
    last sample below 0.05 m/s (t = 6.90 s) to the first above 1 m/s
    (10.24 s); a series that stays below 20 % of the descent gives none;
    a wrong window (the whole run) or the log's slope taken on H itself
    would differ by far more. The incidence: the canopy straight above
    the payload, the relative wind 30 deg off its axis and the force 5
    deg off it (exact to 1e-9)."""
    import numpy as np
    t = np.arange(0, 12.0 + 1e-9, 0.01)
    down = np.array([0.0, 0.0, -1.0])
    velocity = np.stack([1.5 + 0 * t, 0.4 * np.sin(2 * math.pi * 0.25 * t),
                         -5.0 + 0 * t], axis=1)
    g = report.glide(t, velocity, down, 5.0)
    close("glide: mean speed across gravity", g["speed"], 1.5, 1e-9, "m/s")
    close("glide: angle from the vertical", g["angle"],
          math.degrees(math.atan2(1.5, 5.0)), 1e-9, "deg")
    H = 1e-4 * np.exp(0.9 * t)
    V = 5.0 + 0 * t
    gr = report.swing_growth(t, H, V)
    close("departure: growth rate", gr["rate"], 0.9, 0.9e-9, "1/s")
    close("departure: window start", gr["start"], 6.90, 1e-9, "s")
    close("departure: window end", gr["end"], 10.24, 1e-9, "s")
    # the canopy straight above the payload, the relative wind 30 deg off
    # the vertical, the force 5 deg off the axis: exact angles (1e-9)
    n = len(t)
    axis = np.tile([0.0, 0.0, 2.0], (n, 1))
    a = math.radians(30.0)
    falling = np.tile([-5.0 * math.sin(a), 0.0, -5.0 * math.cos(a)], (n, 1))
    b = math.radians(5.0)
    force = np.tile([0.0, 100.0 * math.sin(b), 100.0 * math.cos(b)], (n, 1))
    inc = report.incidence(t, axis, falling, force)
    close("incidence: relative wind to the axis", inc["incidenceMean"], 30.0,
          1e-9, "deg")
    close("incidence: force off the axis", inc["forceOffAxisMax"], 5.0,
          1e-9, "deg")
    check("no departure below 20 % of the descent",
          report.swing_growth(t, 0.19 * V * H / H.max(), V) is None, "None")


def test_canopy_load(tmp):
    """canopy_load: the load's mean vector and spread over the interval,
    and no moment without canopy.h5. Force component k = a_k + b_k sin(2
    pi t / T) sampled at T/40 over 3 whole periods from t = 0: the
    trapezoidal weights give the sample sums, whose sin and sin^2 sums over
    whole periods are exactly 0 and N/2, so the mean is a_k and the std
    |b_k| / sqrt(2) to round-off (1e-12)."""
    t = np.linspace(0.0, 3.0, 121)
    a = np.array([1.5, -2.0, 300.0])
    b = np.array([0.5, 0.0, -20.0])
    force = a[None, :] + np.outer(np.sin(2 * math.pi * t), b)
    load = report.canopy_load(tmp, t, force, 0.0, 3.0)
    close("load: mean vector", max(abs(x - y) for x, y in
                                   zip(load["force"], a)), 0.0, 1e-12, "N")
    close("load: spread", max(abs(x - abs(y) / math.sqrt(2)) for x, y in
                              zip(load["forceStd"], b)), 0.0, 1e-12, "N")
    check("load: no moment without canopy.h5", load["moment"] is None and
          "canopy.h5" in load["momentNote"], load["momentNote"])


def main():
    tmp = tempfile.mkdtemp(prefix="canopy-report-")

    def body():
        case, r = test_restarts_and_statistics(tmp)
        test_half_bin_and_direction(tmp)
        test_breathing_band()
        test_not_resolved(tmp)
        test_missing_quantities(tmp)
        test_command_line(tmp, case, r)
        test_references(tmp, case)
        test_mean_confidence(tmp)
        test_swing(tmp)
        test_departure_and_glide()
        test_canopy_load(tmp)
    return run_checks(tmp, body, "report")


if __name__ == "__main__":
    sys.exit(main())
