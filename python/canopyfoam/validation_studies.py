"""validation_studies.py — the validation studies: each a name, a title and the runs it compares (validation_runs.py)."""

from .validation_runs import (CROSSWIND_T10, DISC_LES_RETRACTED_RUNS,
                              DISC_LOW_RE_RUNS, DISC_RETRACTED_40S_RUNS,
                              DISC_RETRACTED_RUNS, DISC_TILTED_RUNS,
                              DISC_TUTORIAL_40S_RUNS, FINE_CLOTH_SOURCE,
                              FINE_CLOTH_SPEED, FIRST_SOURCE, MAIN_JOB_RUN,
                              SEVEN_RETRACTED_LES_RUNS,
                              SEVEN_RETRACTED_RUNS, SEVEN_TUTORIAL_80S,
                              T10_FINE_SOURCE, TILT_ANGLES)

STUDIES = [
    ("default7ft", "7 ft canopy: the main job (the tutorial's default)",
     [MAIN_JOB_RUN, "7ft-cpd12-markerhalf-40s", "7ft-default",
      "7ft-default-triangleMean", "7ft-default-12s",
      "7ft-default-follower", "7ft-stiff",
      "7ft-free", "7ft-narrow-balanced", "7ft-narrow-default",
      "7ft-h0.15-fullLoad-16s"]),
    ("domain7ft", "7 ft canopy on the guide wire: the box's width (the "
     "main job: 18 cells across D0 at the canopy, the cloth without "
     "stiffness in compression, read over 8-12 s)",
     ["7ft-default-w5.6", "7ft-default-12s", "7ft-default-w11"]),
    ("domain7ftLong", "7 ft canopy on the guide wire: the box's width "
     "over a long window (the main job's set-up: 18 cells across D0 at the "
     "canopy, from rest to 40 s, read over 10-40 s)",
     ["7ft-default-w5.6-40s", "7ft-default-markers-40s",
      "7ft-default-w11-40s"]),
    ("domain7ftStiff", "7 ft canopy on the guide wire: the box's width "
     "(12 cells across D0 at the canopy, the seed's cloth as stiff in "
     "compression as in tension, read over 5-8 s)",
     ["7ft-w5.6", "7ft-stiff", "7ft-w11"]),
    ("tutorialsWide", "The other tutorials on the wide box (8 D0, nested "
     "refinement, 11 cells across D0; the T-10's default 13, the crosses' "
     "22 across their span)",
     ["T10-cpd13-default", "T10-skirt-cpd13-default", "T10-skirt-default",
      "T10-default", "T10-m163-default", "G11-default",
      "G11-folded-default", "C9-default", "cross-default",
      "cross-folded-default"]),
    ("resolution7ft", "7 ft canopy on the guide wire: cells across D0 at "
     "the canopy, the tutorial's cloth without stiffness in compression "
     "(box 8 D0 wide; from rest to 12 s, read over 5-12 s)",
     ["7ft-compression0", "7ft-cpd18-compression0", "7ft-cpd27-compression0",
      "7ft-cpd40-compression0"]),
    ("resolution7ftHeld", "7 ft canopy on the guide wire: cells across D0 "
     "at the canopy, the tutorial as it is (the cloth without stiffness in "
     "compression, the pressure load held over each step; box 8 D0 wide; "
     "from rest to 12 s, read over 5-12 s)",
     ["7ft-cpd12-held", "7ft-cpd18-held", "7ft-cpd27-held",
      "7ft-cpd40-held"]),
    ("resolution7ftSteady", "7 ft canopy on the guide wire, the cloth "
     "without stiffness in compression: cells across D0 in steady descent "
     "(from rest to 45 s, read over 30-45 s)",
     ["7ft-cpd12-45s", "7ft-cpd18-45s", "7ft-cpd27-45s"]),
    ("pressureLoad7ft", "7 ft canopy: the pressure jump's load held over "
     "each step (the tutorial) against following the cloth within the "
     "structure's sub-steps, with those sub-steps at Lambda dt <= 2 and "
     "<= 1 (the main job: 18 cells across D0, read over 8-12 s), and in "
     "the domain study's boxes",
     ["7ft-default-12s", "7ft-default-follower", "7ft-default-omega1",
      "7ft-default-follower-w11", "7ft-default-omega1-w11",
      "7ft-default-omega1-w5.6"]),
    ("hingeDamping7ft", "7 ft canopy: the hinge dashpots' rate in the "
     "main job (18 cells across D0, the cloth without stiffness in "
     "compression, read over 8-12 s)",
     ["7ft-default-12s", "7ft-default-bend1000"]),
    ("hingeDampingCells7ft", "7 ft canopy: the main job with and without "
     "the hinge dashpots, on the load taken from the cells (18 cells "
     "across D0, read over 8-12 s)",
     ["7ft-default-12s", "7ft-default-bend0"]),
    ("resolution7ftCells", "7 ft canopy on the guide wire, the tutorial "
     "as it is (the load from the cells, the cloth's edge 1.25 finest cells "
     "at every level): cells across D0 at the canopy (box 8 D0 wide; from "
     "rest to 15 s, read over 10-15 s)",
     ["7ft-cpd12-15s", "7ft-default", "7ft-cpd27-15s", "7ft-cpd40-15s"]),
    ("kernelFilter7ft", "7 ft canopy: the stabiliser's balance seen "
     "through the IB kernel (the tutorial, addedMass.filter kernel) against "
     "each triangle's mean (triangleMean), and without the hinge dashpots "
     "(the main job: 18 cells across D0, to 15 s, read over 10-15 s)",
     ["7ft-default", "7ft-default-triangleMean", "7ft-default-bend0-15s"]),
    ("balance7ft", "7 ft canopy: the stabiliser's balance in the "
     "structure's sub-steps, the last sub-step's end acceleration "
     "(endOfStep) against the step's mean acceleration (stepMean) (the "
     "main job: 18 cells across D0, read over 8-12 s)",
     ["7ft-default-12s", "7ft-default-stepMean"]),
    ("tapes7ft", "7 ft canopy: the suspension lines run on over the canopy "
     "as radial tapes (the main job: 18 cells across D0, read over 8-12 s)",
     ["7ft-default-12s", "7ft-default-tapes"]),
    ("materialDamping7ft", "7 ft canopy: nylon's material damping as "
     "Kelvin-Voigt dashpots in the main job (loss factor 0.01 and 0.1 at "
     "2 Hz; 18 cells across D0, read over 8-12 s)",
     ["7ft-default-12s", "7ft-default-loss0.01", "7ft-default-loss0.1"]),
    ("damping7ftLong", "7 ft canopy: the hinge dashpots' rate and nylon's "
     "material damping over a long window (the main job's set-up: 18 cells "
     "across D0, from rest to 40 s, read over 10-40 s; the damped canopy "
     "also to 60 s, read over 26-60 s)",
     ["7ft-default-markers-40s", "7ft-default-bend1000-40s",
      "7ft-default-loss0.1-40s", "7ft-default-loss0.1-60s"]),
    ("damping7ft", "7 ft canopy, the cloth without stiffness in "
     "compression: the hinge dashpots' rate (12 cells across D0, read over "
     "30-45 s)",
     ["7ft-cpd12-45s", "7ft-bend1000-45s", "7ft-undamped-45s"]),
    ("resolution7ftUndamped", "7 ft canopy on the guide wire, the "
     "tutorial without hinge dashpots (bendingDamping 0; the load from the "
     "cells, the cloth's edge 1.25 finest cells at every level): cells "
     "across D0 at the canopy (box 8 D0 wide; from rest to 15 s, read over "
     "10-15 s)",
     ["7ft-cpd12-bend0-15s", "7ft-default-bend0-15s",
      "7ft-cpd27-bend0-15s"]),
    ("resolution7ftUntil2", "7 ft canopy on the guide wire, the tutorial "
     "with the hinge dashpots during the first inflation only (off from 2 "
     "s, fabric.bendingDampingUntil; the load from the cells, the cloth's "
     "edge 1.25 finest cells at every level): cells across D0 at the "
     "canopy (box 8 D0 wide; from rest to 15 s, read over 10-15 s)",
     ["7ft-cpd%d-until2-15s" % n for n in (12, 18, 27)]),
    ("window7ft12", "7 ft canopy on the guide wire, 12 cells across D0, "
     "the tutorial with its hinge dashpots throughout and off from 2 s "
     "(bendingDampingUntil 2): from rest to 15 s read over 10-15 s against "
     "to 40 s read over 10-40 s",
     ["7ft-cpd12-15s", "7ft-cpd12-until2-15s", "7ft-cpd12-40s",
      "7ft-cpd12-until2-40s"]),
    ("resolution7ftUntil2Long", "7 ft canopy on the guide wire, the "
     "tutorial with its markers a cell apart (the hinge dashpots off from 2 "
     "s): cells across D0 "
     "at the canopy over a long window (box 8 D0 wide; from rest to 40 s, "
     "read over 10-40 s)",
     ["7ft-cpd12-until2-40s", "7ft-cpd18-until2-40s",
      "7ft-cpd27-until2-40s"]),
    ("quasiNewtonReuse7ft", "7 ft canopy on the guide wire, the "
     "undamped tutorial (12 cells across D0): IQN-ILS reusing the columns "
     "of 8 past time steps (the tutorial's), of none and of 16, going on "
     "from the main job's 40 s write to 41.5 s",
     ["7ft-cpd12-markerhalf-reuse%d-41.5s" % n for n in (8, 0, 16)]),
    ("iterations7ft", "7 ft canopy on the guide wire, the undamped tutorial "
     "(12 cells across D0): nylon's material damping (loss factor 0.02 "
     "and 0.1 at 2 Hz) against the tutorial's undamped cloth and lines, "
     "the coupling's iterations in steady descent, each going on from the "
     "main job's 40 s write to 41.5 s, and the step-to-step change of the "
     "cloth's velocity over the next 0.15 s",
     ["7ft-cpd12-markerhalf-reuse8-41.5s",
      "7ft-cpd12-markerhalf-loss0.02-41.5s",
      "7ft-cpd12-markerhalf-loss0.1-41.5s",
      "7ft-cpd12-markerhalf-steps-41.65s",
      "7ft-cpd12-markerhalf-loss0.02-steps-41.65s"]),
    ("damping7ftTutorial", "7 ft canopy on the guide wire, the undamped "
     "tutorial: nylon's material damping (loss factor "
     "0.02 at 2 Hz) against the tutorial's undamped cloth and lines at 12 "
     "and 18 cells across D0, from rest to 40 s, read over 10-40 s, and "
     "at 12 cells on to 80 s, read over 40-80 s",
     ["7ft-cpd12-markerhalf-40s", "7ft-cpd12-markerhalf-loss0.02-40s",
      "7ft-cpd18-markerhalf-40s", "7ft-cpd18-markerhalf-loss0.02-40s",
      "7ft-cpd12-markerhalf-80s", "7ft-cpd12-markerhalf-loss0.02-80s"]),
    ("resolution7ftDamped", "7 ft canopy on the guide wire, the tutorial "
     "with nylon's material damping (loss factor 0.02 at 2 Hz in the cloth "
     "and the lines; the hinge dashpots off from 2 s, the markers half a "
     "cell apart): cells across D0 at the canopy (box 8 D0 wide; from rest "
     "to 40 s, read over 10-40 s)",
     ["7ft-cpd%d-markerhalf-loss0.02-40s" % n for n in (12, 18, 27)]),
    ("levels7ftDamped", "7 ft canopy on the guide wire, the tutorial as it "
     "is (nylon's damping, loss factor 0.02 at 2 Hz, in the cloth and the "
     "lines): 12 cells across D0 (the main job) and 18, each from rest to "
     "80 s, and 27, from rest to 40 s going on to 80 s, read over 40-80 s",
     ["7ft-cpd%d-damped-80s" % n for n in (12, 18)]
     + ["7ft-cpd27-markerhalf-loss0.02-80s"]),
    ("gores7ft", "7 ft canopy on the guide wire, the tutorial as it is "
     "(nylon's damping, loss factor 0.02 at 2 Hz): 16 gores and lines (the "
     "drop test's canopy) against 32, at 18 cells across D0 with the "
     "fabric's edge at 1.25 and 0.83 finest cells (box 8 D0 wide; from rest "
     "to 40 s, read over 10-40 s)",
     ["7ft-cpd18-markerhalf-loss0.02-40s", "7ft-cpd18-gores32-40s",
      "7ft-cpd18-edge0.83-gores16-40s", "7ft-cpd18-edge0.83-gores32-40s"]),
    ("discTutorial7ft", "The fluid side alone on the 7 ft tutorial's "
     "forcing: the rigid impermeable disc of study disc7ft (D0 = 2.134 m, "
     "5 m/s) with the markers half a cell apart, at 12, 18 and 27 cells "
     "across D0, and at 18 with the air's pressure sampled off the disc as "
     "the cloth's load (to 20 s, read over 5-20 s)",
     ["disc-markerhalf-cpd%d" % n for n in (12, 18, 27)]
     + ["disc-markerhalf-sampled-cpd18"]),
    ("discEdge7ft", "Where the IB forcing puts a free edge: the rigid "
     "impermeable disc of D0 = 2.134 m at Re = 10 (a steady wake; the air's "
     "viscosity raised to 1.067 m^2/s, 5 m/s), on the tutorial's forcing "
     "at 8, 12 and 18 cells across D0, its edge retracted by 0 and 1 cell "
     "(serial, to 10 s, read over 7-10 s)",
     [r.ident for r in DISC_LOW_RE_RUNS]),
    ("discRetracted7ft", "The disc of study discTutorial7ft (5 m/s in "
     "air, Re 7e5) with its free edge retracted by 1.1 cells (study "
     "discEdge7ft), at 12 and 18 cells across D0, its load the IB force's "
     "reaction and at 18 the air's sampled pressure, against the same "
     "without the retraction (to 20 s, read over 5-20 s)",
     [r.ident for r in DISC_RETRACTED_RUNS]
     + ["disc-markerhalf-cpd%d" % n for n in (12, 18)]
     + ["disc-markerhalf-sampled-cpd18"]),
    ("discWake7ft", "The disc of study discRetracted7ft (its free edge "
     "retracted by 1.1 cells, 5 m/s in air) after its wake leaves the "
     "symmetric start: to 20 s read over 5-20 s against going on to 40 s "
     "read over 20-40 s, on its axis and with the stream 2 degrees off it "
     "(12 cells across D0), laminar and LES (WALE, LUST convection), at 12 "
     "and 18 cells across D0, and the disc without the retraction from "
     "rest to 40 s",
     [r.ident for source, extended in zip(
         DISC_RETRACTED_RUNS + DISC_TILTED_RUNS, DISC_RETRACTED_40S_RUNS)
      for r in (source, extended)]
     + [r.ident for r in DISC_LES_RETRACTED_RUNS + DISC_TUTORIAL_40S_RUNS]),
    ("retraction7ft", "7 ft canopy on the guide wire, the tutorial as it "
     "is with its hem retracted by 1.1 cells (study discEdge7ft) against "
     "it as it is, at 12 and 18 cells across D0 (box 8 D0 wide; from rest "
     "to 40 s, read over 10-40 s)",
     [r.ident for r in SEVEN_RETRACTED_RUNS[:2]]    # the 27-cell: not run
     + ["7ft-cpd%d-markerhalf-loss0.02-40s" % n for n in (12, 18)]),
    ("retraction7ftLES", "7 ft canopy on the guide wire, the tutorial as "
     "it is with its hem retracted by 1.1 cells: laminar against LES "
     "(WALE, LUST convection; the retracted disc's drag with them: study "
     "discWake7ft) at 12 cells across D0 (box 8 D0 wide; from rest to 40 "
     "s, read over 10-40 s)",
     [SEVEN_RETRACTED_RUNS[0].ident]
     + [r.ident for r in SEVEN_RETRACTED_LES_RUNS]),
    ("load7ftSampled", "7 ft canopy on the guide wire, the tutorial as it "
     "is at 12 cells across D0: the cloth's load the IB force's reaction "
     "taken from the cells (the tutorial's) against the air's pressure "
     "sampled 3 cells off each side of the markers, without and with the "
     "hinge dashpots after 2 s (from rest to 40 s, read over 10-40 s; "
     "with the dashpots to 10 s, read over 3-7.5 s)",
     ["7ft-cpd12-markerhalf-loss0.02-40s", "7ft-cpd12-sampled-40s",
      "7ft-cpd12-sampled-dashpots-10s"]),
    ("turbulence7ftDamped", "7 ft canopy on the guide wire, the tutorial "
     "as it is (nylon's damping, loss factor 0.02 at 2 Hz): laminar against "
     "LES (WALE, LUST convection) at 12 cells across D0 (the main job's "
     "set-up, from rest to 70 s, read over 30-70 s) and at 18 (from rest to "
     "80 s, read over 40-80 s)",
     ["7ft-cpd12-damped-70s", "7ft-cpd12-damped-LES-70s",
      "7ft-cpd18-damped-80s", "7ft-cpd18-damped-LES-80s"]),
    ("resolution7ftMarkerHalf", "7 ft canopy on the guide wire, the "
     "undamped tutorial (the hinge dashpots off from 2 s, the markers half "
     "a cell apart): cells across D0 at the canopy (box 8 D0 wide; from "
     "rest to 40 s, read over 10-40 s)",
     ["7ft-cpd%d-markerhalf-40s" % n for n in (12, 18, 27)]
     + ["7ft-cpd40-narrow-markerhalf-40s"]),
    ("mainJobLevel7ft", "7 ft canopy on the guide wire, the undamped tutorial"
     ": the main job's level (issue 31 §4), 12 and 13 cells across D0 "
     "(box 8 D0 wide; from rest to 40 s, read over 10-40 s) against the "
     "converged value of resolution7ftMarkerHalf",
     ["7ft-cpd%d-markerhalf-40s" % n for n in (12, 13)]),
    ("numerics7ftMarkerHalf", "7 ft canopy on the guide wire, the "
     "undamped tutorial (12 cells across D0, the markers half a cell "
     "apart): the time step (maxCo 0.5 and maxDeltaT 0.01 against 0.25 "
     "and 0.005) and the coupling's tolerance (5e-3 against 2.5e-3 and "
     "1e-2; from rest to 40 s, read over 10-40 s, and going on from the "
     "main job's 40 s write to 80 s, read over 40-80 s)",
     ["7ft-cpd12-markerhalf-40s", "7ft-cpd12-markerhalf-co0.25-40s",
      "7ft-cpd12-markerhalf-tol2.5e-3-40s",
      "7ft-cpd12-markerhalf-tol1e-2-40s", "7ft-cpd12-markerhalf-80s",
      "7ft-cpd12-markerhalf-tol2.5e-3-80s"]),
    ("coarse7ftTutorial", "7 ft canopy on the guide wire, the tutorial "
     "with its markers a cell apart on 8 cells across D0 (the fabric's edge 0.33 m), with the "
     "tutorial's time step and half of it (from rest to 40 s, read over "
     "10-40 s)", ["7ft-cpd8-until2-40s", "7ft-cpd8-until2-co0.25-40s"]),
    ("domain7ftTutorial", "7 ft canopy on the guide wire, the tutorial "
     "with its markers a cell apart (12 cells across D0, the hinge "
     "dashpots off from 2 s): the "
     "box's width (from rest to 40 s, read over 10-40 s)",
     ["7ft-cpd12-until2-w5.6-40s", "7ft-cpd12-until2-40s",
      "7ft-cpd12-until2-w11-40s"]),
    ("timeStep7ftTutorial", "7 ft canopy on the guide wire, the tutorial "
     "with its markers a cell apart (12 cells across D0): the time step (maxCo 0.5 and "
     "maxDeltaT 0.01 against 0.25 and 0.005; from rest to 40 s, read over "
     "10-40 s)", ["7ft-cpd12-until2-40s", "7ft-cpd12-until2-co0.25-40s"]),
    ("edgeLength7ftTutorial", "7 ft canopy on the guide wire, the "
     "tutorial with its markers a cell apart (12 cells across D0): the "
     "structure's resolution "
     "(fabric edge 1.25, 0.83 and 0.56 finest cells; from rest to 40 s, "
     "read over 10-40 s)",
     ["7ft-cpd12-until2-40s", "7ft-cpd12-until2-edge0.83-40s",
      "7ft-cpd12-until2-edge0.56-40s"]),
    ("markers7ftTutorial", "7 ft canopy on the guide wire, the tutorial "
     "(12 cells across D0, the hinge dashpots off from 2 s): the cloth's "
     "markers a cell apart and closer (forcing.markerSpacing), for the "
     "fabric's edge at 1.25, 0.83 and 0.56 finest cells (from rest to 40 "
     "s, read over 10-40 s)", ["7ft-cpd12-until2-40s",
                       "7ft-cpd12-until2-markers0.5-40s",
                       "7ft-cpd12-until2-markers0.25-40s",
                       "7ft-cpd12-until2-edge0.83-40s",
                       "7ft-cpd12-until2-edge0.83-markers0.5-40s",
                       "7ft-cpd12-until2-edge0.56-40s",
                       "7ft-cpd12-until2-edge0.56-markers0.25-40s"]),
    ("edgeLength7ftTutorialTo80", "7 ft canopy on the guide wire, the "
     "tutorial with its markers a cell apart (12 cells across D0): the "
     "structure's resolution "
     "over a longer window (fabric edge 1.25, 0.83 and 0.56 finest cells; "
     "each run of study edgeLength7ftTutorial going on from 40 s to 80 s, "
     "read over 40-80 s)", [r.ident for r in SEVEN_TUTORIAL_80S]),
    ("resolution7ftUndampedContinued", "7 ft canopy on the guide wire, "
     "the tutorial without hinge dashpots, each level continuing the "
     "damped level's inflated canopy at 15 s (the load from the cells, the "
     "cloth's edge 1.25 finest cells at every level; to 8 s, read over 3-8 "
     "s)", ["7ft-cpd%d-bend0-cont" % n for n in (12, 18, 27)]),
    ("resolution7ftStiff", "7 ft canopy on the guide wire: cells across D0 "
     "at the canopy, the seed's cloth as stiff in compression as in tension "
     "(box 8 D0 wide; to 8 s, read over 5-8 s)",
     ["7ft-stiff", "7ft-cpd18", "7ft-cpd27"]),
    ("freeDomain7ft", "7 ft canopy in free flight: the box's width, before the swing (12 cells across D0)",
     ["7ft-free-w2.8", "7ft-free-w5.6", "7ft-free", "7ft-free-w11"]),
    ("freeResolution7ft", "7 ft canopy in free flight: cells across D0, before the swing",
     ["7ft-free", "7ft-free-cpd18"]),
    ("freeDescent7ft", "7 ft canopy in free flight: the swinging descent "
     "over 10-40 s (12 cells across D0)", ["7ft-free40"]),
    ("departureT10", "T-10 at 163 kg in free flight: what sets the "
     "departure from the vertical descent (13 cells across D0 unless said, "
     "to 20 s, read over 10-20 s)",
     ["T10-free-cpd13-m163-20s", "T10-free-cpd13-m163-tol1.25e-3",
      "T10-free-cpd13-m163-co0.25", "T10-free-cpd20-m163",
      "T10-free-cpd13-m163-LES", "T10-free-cpd13-m163-am1.35",
      "T10-free-cpd13-m163-normal"]),
    ("incidenceT10", "T-10 at incidence: its inflated shape held still in "
     "a tilted stream (the fluid side alone; 13 cells across D0, 6.66 m/s, "
     "to 30 s, read over 15-30 s)",
     ["T10-tilt%d" % a for a in TILT_ANGLES]),
    ("incidenceT10Resolution", "T-10 held at 30° to the stream: 13 and "
     "20 cells across D0 (6.66 m/s, to 30 s, read over 15-30 s)",
     ["T10-tilt30", "T10-tilt30-cpd20"]),
    ("incidenceT10Free", "T-10 at incidence with its cloth free: on the "
     "guide wire (axis vertical) in a horizontal wind, 163 kg, 13 cells "
     "across D0, to 30 s, read over 15-30 s",
     sorted(CROSSWIND_T10)),
    ("pivotT10", "T-10 with the payload alone on the guide wire: the "
     "canopy free to turn about the payload, the payload kept from "
     "swinging (163 kg, 13 cells across D0 unless said, from the inflated "
     "state, to 30 s, read over 15-30 s)",
     ["T10-pivot-crosswind0", "T10-pivot-crosswind20",
      "T10-pivot-crosswind0-cpd20"]),
    ("forcedTurnT10", "T-10 turned about its payload by an imposed "
     "oscillation: the air's stiffness and damping in pitch (its inflated "
     "shape held rigid, 13 cells across D0 unless said, 6.66 m/s along the "
     "axis, from 10 s, to 110 s, read over 20-110 s)",
     ["T10-held0", "T10-turn10-T5", "T10-turn10-T10", "T10-turn20-T5",
      "T10-turn20-T7",
      "T10-turn20-T8.5", "T10-turn20-T10", "T10-turn20-T12.5",
      "T10-turn20-T15", "T10-turn20-T10-cpd20"]),
    ("incidence7ft", "7 ft flat circular canopy at incidence: its inflated "
     "shape held still in a tilted stream (the fluid side alone; 18 cells "
     "across D0, 6.22 m/s, to 8 s, read over 4-8 s)",
     ["7ft-tilt%d" % a for a in TILT_ANGLES]),
    ("freeFlight", "The parachutes in free flight: the swing and the "
     "glide (the T-10 at 13 cells across D0 to 60 s, read over 15-60 s; "
     "the 7 ft canopy at the main job's set-up to 15 and 30 s, read from "
     "10 s; the cross on the full-load scheme at 11 cells across its span "
     "to 20 s, read over 10-20 s)",
     ["7ft-default-free-15s", "7ft-default-free-30s", "T10-free-cpd13-m100",
      "T10-free-cpd13-m163", "cross-fullLoad-20s"]),
    ("crossResolution", "Cross parachute in free flight: cells across the "
     "span (the full-load scheme, from the flat start to 8 s, read over 4-8 "
     "s; the 11-cell set-up also on 1 rank to 20 s)",
     ["cross-cpd11-8s", "cross-cpd16-8s", "cross-cpd22-8s",
      "cross-fullLoad-20s"]),
    ("crossStarts", "Cross parachute from the flat and the folded start "
     "on the tutorials' set-up (the full-load scheme, 22 cells across the "
     "span, to 4 s, read over the last third)",
     ["cross-default", "cross-folded-default"]),
    ("turbulence7ftConverged", "7 ft canopy: laminar against LES (WALE, "
     "LUST convection) on the converged set-up: the main job's over 10-40 "
     "s and the resolution study's finest level (27 cells across D0) over "
     "5-12 s",
     ["7ft-default-markers-40s", "7ft-default-LES-40s", "7ft-cpd27-held",
      "7ft-cpd27-LES"]),
    ("steadyLarge", "C-9 and 1/3-scale G-11 on a guide wire in steady "
     "descent (13 cells across D0, to 60 s, read over 30-60 s; also to 120 "
     "s, read over 60-120 s)",
     ["C9-cpd13-60s", "C9-cpd13-120s", "G11-cpd13-60s", "G11-cpd13-120s"]),
    ("timeStep7ft", "7 ft canopy: the time step (the main job: 18 cells "
     "across D0, the cloth without stiffness in compression, read over "
     "8-12 s)", ["7ft-default-12s", "7ft-default-co0.25"]),
    ("edgeLength7ftLong", "7 ft canopy: the structure's resolution over a "
     "long window (the main job's set-up: 18 cells across D0, from rest to "
     "40 s, read over 10-40 s; fabric edge 1.25, 0.83 and 0.56 finest "
     "cells)",
     ["7ft-default-markers-40s", "7ft-default-edge0.83-40s",
      "7ft-default-edge0.56-40s"]),
    ("edgeAgainstCells7ft", "7 ft canopy: the fabric's edge against the "
     "air's resolution (the tutorial's cloth and load; 18 and 27 cells "
     "across D0; edge 0.148, 0.099 and 0.066 m; from rest to 12 s, each "
     "compared over 8-12 s)",
     ["7ft-default-12s", "7ft-default-edge0.83", "7ft-default-edge0.56",
      "7ft-cpd27-held", "7ft-cpd27-edge0.83", "7ft-cpd27-edge0.56"]),
    ("inflatedStart7ft", "7 ft canopy on the guide wire: the inflated "
     "canopy started in a uniform stream (%s's canopy at 12 s, at rest in "
     "the frame, every node and the air at %g m/s; the 0.044 m cloth on the "
     "narrow refinement, 18 cells across D0 to 6 s and 27 to 5 s, read from "
     "2 s) against the same cloth and air from rest"
     % (FIRST_SOURCE, FINE_CLOTH_SPEED),
     ["7ft-inflated-cpd18", "7ft-inflated-cpd27", FIRST_SOURCE]),
    ("resolution7ftMapped", "7 ft canopy on the guide wire: cells "
     "across D0 at the canopy with the cloth held at its finest (fabric "
     "edge 0.044 m) on the narrow refinement, each level continuing %s at "
     "10 s (its air's fields mapped onto the level's mesh, its canopy at "
     "rest in the frame at the payload's speed), to 4 s, read over 1-4 s"
     % FINE_CLOTH_SOURCE,
     ["7ft-mapped-cpd%d" % n for n in (18, 27, 40)] + [FINE_CLOTH_SOURCE]),
    ("resolution7ftMappedCells", "7 ft canopy on the guide wire, the "
     "tutorial's load (taken from the cells): cells across D0 at the canopy "
     "with the cloth held at its finest (fabric edge 0.044 m) on the narrow "
     "refinement, each level continuing %s at 10 s (its air's fields mapped "
     "onto the level's mesh, its canopy at rest in the frame at the "
     "payload's speed), to 5 s, read over 2-5 s" % FINE_CLOTH_SOURCE,
     ["7ft-mapped-cells-cpd%d" % n for n in (18, 27, 40)]
     + [FINE_CLOTH_SOURCE]),
    ("resolutionT10Mapped", "T-10 at 163 kg on a guide wire, the extended "
     "skirt: cells across D0 at the canopy with the cloth held at 0.446 m "
     "(the 30-cell level's edge), each level continuing %s at 80 s (its "
     "air's fields mapped onto the level's mesh, its canopy at rest in the "
     "frame at the payload's speed), to 12 s, read over 2-12 s"
     % T10_FINE_SOURCE,
     ["T10-mapped-cpd%d" % n for n in (13, 20, 30)] + [T10_FINE_SOURCE]),
    ("markersT10", "T-10 at 163 kg on a guide wire, the extended "
     "skirt: the markers a cell apart (the tutorial) and half a cell apart "
     "(forcing.markerSpacingCells 0.5) at 13, 20 and 30 cells across D0 "
     "with the cloth held at 0.446 m, each level continuing %s at 80 s, to "
     "12 s, read over 2-12 s" % T10_FINE_SOURCE,
     [r % n for n in (13, 20, 30) for r in ("T10-mapped-cpd%d",
                                            "T10-mapped-cpd%d-markerhalf")]
     + [T10_FINE_SOURCE]),
    ("dashpotsT10", "T-10 at 163 kg on a guide wire, the extended skirt: "
     "with the hinge dashpots (the tutorial, 10 000 /s) and without them, "
     "at 13 and 20 cells across D0 with the cloth held at 0.446 m, each "
     "level continuing %s at 80 s, to 12 s, read over 2-12 s"
     % T10_FINE_SOURCE,
     [r % n for n in (13, 20) for r in ("T10-mapped-cpd%d",
                                        "T10-mapped-cpd%d-bend0")]
     + [T10_FINE_SOURCE]),
    ("resolutionT10MarkerHalf", "T-10 at 163 kg on a guide wire, the "
     "extended skirt, the markers half a cell apart: cells across D0 at "
     "the canopy with the cloth held at 0.446 m, each level continuing %s "
     "at 80 s, to 12 s, read over 2-12 s" % T10_FINE_SOURCE,
     ["T10-mapped-cpd%d-markerhalf" % n for n in (13, 20, 30)]
     + [T10_FINE_SOURCE]),
    ("markersT10Kernel", "T-10 at 163 kg on a guide wire, the extended "
     "skirt, on the 7 ft tutorial's coupling (the load taken from the "
     "cells, the stabiliser's balance seen through the IB kernel) with the "
     "markers half a cell apart: the tutorial's cloth from rest (13 cells "
     "across D0, to 80 s, read over 50-80 s) against each marker's own "
     "force with the markers a cell and half a cell apart",
     ["T10-skirt-cpd13-m163", "T10-skirt-cpd13-m163-markerhalf",
      "T10-skirt-cpd13-m163-kernel-markerhalf"]),
    ("payloadT10KernelMarkerHalf", "T-10 on a guide wire, the extended "
     "skirt, on the 7 ft tutorial's coupling with the markers half a cell "
     "apart: descent against payload (the tutorial's cloth from rest, 13 "
     "cells across D0, box 8 D0 wide, to 80 s, read over 50-80 s)",
     ["T10-skirt-cpd13-m%d-kernel-markerhalf" % m
      for m in (100, 163, 300, 600)]),
    ("payloadT10Tutorial", "T-10 on a guide wire, the tutorial as it is "
     "(the extended skirt on the 7 ft tutorial's coupling, the markers half "
     "a cell apart): descent against payload (from rest, 13 cells across "
     "D0, box 8 D0 wide, to 120 s, read over 80-120 s)",
     ["T10-cpd13-m%d-120s" % m for m in (100, 163, 300, 600)]),
    ("dashpotsT10Tutorial", "T-10 at 163 kg on a guide wire, the tutorial "
     "as it is: the hinge dashpots throughout (the tutorial) and off from "
     "10 s (fabric.bendingDampingUntil 10; from rest, 13 cells across D0, "
     "to 120 s, read over 80-120 s)",
     ["T10-cpd13-m163-120s", "T10-cpd13-m163-until10-120s"]),
    ("dashpotsT10Free", "T-10 at 163 kg in free flight, the tutorial as it "
     "is: the hinge dashpots throughout (the tutorial) and off from 10 s "
     "(fabric.bendingDampingUntil 10; from rest, 13 cells across D0, to 60 "
     "s, read over 15-60 s)",
     ["T10-cpd13-free-m163", "T10-cpd13-free-m163-until10"]),
    ("couplingC9", "C-9 at 100 kg on a guide wire: its tutorial's coupling "
     "against the T-10 tutorial's (13 cells across D0, to 120 s, read over "
     "60-120 s)", ["C9-cpd13-120s", "C9-cpd13-coupling7ft-120s"]),
    ("freeT10Tutorial", "T-10 in free flight, the tutorial as it is: its "
     "default (100 kg to 20 s) and 163 kg to 60 s, read over 15-60 s "
     "(13 cells across D0, box 8 D0 wide)",
     ["T10-cpd13-default", "T10-cpd13-free-m163"]),
    ("resolutionT10KernelMarkerHalf", "T-10 at 163 kg on a guide wire, the "
     "extended skirt, on the 7 ft tutorial's coupling with the markers half "
     "a cell apart: cells across D0 at the canopy with the cloth held at "
     "0.446 m, each level continuing %s at 80 s, to 12 s, read over 2-12 s"
     % T10_FINE_SOURCE,
     ["T10-mapped-cpd%d-kernel-markerhalf" % n for n in (13, 20, 30)]
     + [T10_FINE_SOURCE]),
    ("resolutionT10Kernel", "T-10 at 163 kg on a guide wire, the "
     "extended skirt, on the 7 ft tutorial's coupling (the load taken from "
     "the cells, the stabiliser's balance seen through the IB kernel): "
     "cells across D0 at the canopy with the cloth held at 0.446 m, each "
     "level continuing %s at 80 s, to 12 s, read over 2-12 s"
     % T10_FINE_SOURCE,
     ["T10-mapped-cpd%d-kernel" % n for n in (13, 20, 30)]
     + [T10_FINE_SOURCE]),
    ("cellReactionT10", "T-10 at 163 kg on a guide wire, the extended "
     "skirt: the load taken from the cells (coupling.load.reaction cells) "
     "against each marker's own, at 13 and 20 cells across D0 (each "
     "continuing %s at 80 s, to 12 s, read over 2-12 s)" % T10_FINE_SOURCE,
     ["T10-mapped-cpd13", "T10-mapped-cpd13-cells", "T10-mapped-cpd20",
      "T10-mapped-cpd20-cells"]),
    ("timeStepT10Mapped", "T-10 at 163 kg on a guide wire, the extended "
     "skirt: the time step at 20 cells across D0 (maxCo 0.5 and 0.25; the "
     "0.446 m cloth continuing %s at 80 s, to 12 s, read over 2-12 s)"
     % T10_FINE_SOURCE, ["T10-mapped-cpd20", "T10-mapped-cpd20-co0.25"]),
    ("couplingT10", "T-10 at 163 kg on a guide wire, the extended skirt: "
     "the coupling's iterations at 13 cells across D0 with the stabiliser's "
     "triangle-mean filter, with IQN-ILS and with the stabiliser's "
     "predictor zero, and at 20 cells with the last two "
     "(the 0.446 m cloth continuing "
     "%s at 80 s, to 12 s, read over 2-12 s)" % T10_FINE_SOURCE,
     ["T10-mapped-cpd13", "T10-mapped-cpd13-filter", "T10-mapped-cpd13-iqn",
      "T10-mapped-cpd13-zero", "T10-mapped-cpd20", "T10-mapped-cpd20-iqn",
      "T10-mapped-cpd20-zero"]),
    ("coupling7ft", "7 ft canopy: the main job's coupling, IQN-ILS (the "
     "tutorial; 7ft-default-iqn is the same setting, run before it was "
     "the tutorial's) against Aitken's relaxation (18 cells across D0, to "
     "12 s, read over 8-12 s)",
     ["7ft-default-12s", "7ft-default-iqn", "7ft-default-aitken"]),
    ("edgeLengthT10", "T-10 at 163 kg on a guide wire, the extended skirt: "
     "the structure's resolution at 13 cells across D0 (fabric edge 1.25, "
     "0.83 and 0.54 finest cells, 1.03, 0.683 and 0.446 m; from rest to 80 "
     "s, read over 50-80 s)",
     ["T10-skirt-cpd13-m163", "T10-skirt-cpd13-edge0.83", T10_FINE_SOURCE]),
    ("markersT10Tutorial", "T-10 at 163 kg on a guide wire, the extended "
     "skirt: the markers a cell apart (the tutorial) and half a cell apart "
     "(forcing.markerSpacingCells 0.5) for the fabric's edge at 1.25 and "
     "0.83 finest cells, and the 0.54 edge (one marker per triangle, 0.54 "
     "cells apart), at 13 cells across D0 (from rest to 80 s, read over "
     "50-80 s)",
     ["T10-skirt-cpd13-m163", "T10-skirt-cpd13-m163-markerhalf",
      "T10-skirt-cpd13-edge0.83", "T10-skirt-cpd13-edge0.83-markerhalf",
      T10_FINE_SOURCE]),
    ("timeStep7ftMapped", "7 ft canopy on the guide wire: the time step "
     "at 27 cells across D0 (maxCo 0.5 and 0.25; the 0.044 m cloth "
     "continuing %s at 10 s, to 4 s, read over 1-4 s)" % FINE_CLOTH_SOURCE,
     ["7ft-mapped-cpd27", "7ft-mapped-cpd27-co0.25"]),
    ("narrowRefinement7ft", "7 ft canopy on the guide wire: the finest "
     "box 1.6 D0 wide (the narrow refinement) against the tutorial's 2.6 "
     "D0 (18 cells across D0, the 0.044 m cloth from 7ft-cpd27-edge0.56's "
     "inflated canopy at 5.66 m/s, to 6 s, read over 2-6 s)",
     ["7ft-inflated-cpd18-wide", "7ft-inflated-cpd18"]),
    ("edgeLength7ftCpd27", "7 ft canopy: the structure's resolution at 27 "
     "cells across D0 (the tutorial's cloth and load; fabric edge 1.25, "
     "0.83 and 0.56 finest cells, 0.099, 0.066 and 0.044 m; from rest to "
     "12 s, read over 8-12 s)",
     ["7ft-cpd27-held", "7ft-cpd27-edge0.83", "7ft-cpd27-edge0.56"]),
    ("edgeLength7ft", "7 ft canopy: the structure's resolution (the main "
     "job: 18 cells across D0, the cloth without stiffness in compression, "
     "read over 8-12 s; fabric edge in finest cells)",
     ["7ft-default-edge1.88", "7ft-default-12s", "7ft-default-edge0.83",
      "7ft-default-edge0.56"]),
    ("timeStep7ftStiff", "7 ft canopy: the time step (12 cells across D0, "
     "the seed's stiff cloth)",
     ["7ft-stiff", "7ft-co0.25", "7ft-co0.25-12s"]),
    ("edgeLength7ftStiff", "7 ft canopy: the structure's resolution (12 "
     "cells across D0, the seed's stiff cloth; fabric edge in finest "
     "cells)",
     ["7ft-edge0.83", "7ft-stiff", "7ft-edge1.88"]),
    ("relaxation7ft", "7 ft canopy: Aitken's factor from 0.3 and from 1, "
     "and the coupling's tolerance (12 and 18 cells across D0)",
     ["7ft-stiff", "7ft-relax1", "7ft-tol1e-3", "7ft-tol1e-3-relax1",
      "7ft-tol5e-4-relax1", "7ft-cpd18", "7ft-cpd18-relax1",
      "7ft-cpd18-tol1e-3", "7ft-cpd18-tol1e-3-relax1",
      "7ft-cpd18-tol5e-4-relax1"]),
    ("tolerance7ft", "7 ft canopy: the coupling's tolerance against the "
     "runs' scatter (12 cells across D0, Aitken's factor from 1; splitx: "
     "the same run with the box split across the flow)",
     ["7ft-relax1", "7ft-relax1-splitx", "7ft-tol1e-3-relax1",
      "7ft-tol1e-3-relax1-splitx", "7ft-tol5e-4-relax1",
      "7ft-tol5e-4-relax1-splitx"]),
    ("tolerance7ftLong", "7 ft canopy: the coupling's tolerance over 10-40 "
     "s (12 cells across D0, Aitken's factor from 1)",
     ["7ft-relax1-40s", "7ft-tol1e-3-relax1-40s", "7ft-tol5e-4-relax1-40s",
      "7ft-tol2.5e-4-relax1-40s"]),
    ("resolution7ftLong", "7 ft canopy on the guide wire: cells across D0 "
     "over 10-40 s, after the wake's symmetry breaks (box 8 D0 wide, "
     "coupling to 1e-3)",
     ["7ft-tol1e-3-relax1-40s", "7ft-cpd18-tol1e-3-relax1-40s",
      "7ft-cpd27-tol1e-3-relax1-40s"]),
    ("wrinkling7ft", "7 ft canopy: the cloth's stiffness in compression "
     "(fabric.compressionRatio; from rest to 12 s, read over 5-12 s)",
     ["7ft-relax1", "7ft-compression0.1", "7ft-compression0.01",
      "7ft-compression0", "7ft-edge0.83-compression0",
      "7ft-cpd18-compression0",
      "7ft-cpd27-compression0", "7ft-compression0-40s"]),
    ("disc7ft", "The fluid side alone: a rigid impermeable disc of D0 = "
     "2.134 m in a 5 m/s stream on the 7 ft tutorial's mesh",
     ["disc-cpd12", "disc-cpd18", "disc-cpd27"]),
    ("discLES7ft", "The fluid side alone with LES: the rigid disc of "
     "study disc7ft with the WALE model and LUST convection",
     ["disc-LES-cpd12", "disc-LES-cpd18", "disc-LES-cpd27"]),
    ("tolerance7ftCpd18", "7 ft canopy: the coupling's tolerance against "
     "the runs' scatter (18 cells across D0, Aitken's factor from 1; "
     "splitx: the same run with the box split across the flow)",
     ["7ft-cpd18-relax1", "7ft-cpd18-tol1e-3-relax1",
      "7ft-cpd18-tol1e-3-relax1-splitx", "7ft-cpd18-tol1e-3-pTight-relax1",
      "7ft-cpd18-tol5e-4-relax1",
      "7ft-cpd18-tol5e-4-relax1-splitx", "7ft-cpd18-tol2.5e-4-relax1",
      "7ft-cpd18-tol1e-3-relax1-splitx-30s"]),
    ("timeStep7ftCpd18", "7 ft canopy: the time step (18 cells across D0)",
     ["7ft-cpd18-relax1", "7ft-cpd18-co0.25"]),
    ("edgeLength7ftCpd18", "7 ft canopy: the structure's resolution (18 "
     "cells across D0; fabric edge in finest cells)",
     ["7ft-cpd18-relax1", "7ft-cpd18-edge0.83"]),
    ("freeT10", "T-10 at 163 kg in free flight to 50 s (11 cells across "
     "D0)", ["T10-m163-default", "T10-m163-free50"]),
    ("domainT10", "T-10 at 163 kg on a guide wire: the box's width (11 "
     "cells across D0 at the canopy)",
     ["T10-m163-w5.6", "T10-m163-w8", "T10-m163-w11"]),
    ("resolutionT10", "T-10 at 163 kg on a guide wire: cells across D0 at "
     "the canopy (box 8 D0 wide)", ["T10-m163-w8", "T10-m163-cpd20", "T10-m163-cpd30"]),
    ("skirtT10", "T-10 at 163 kg on a guide wire: the seed's paraboloid "
     "(skirt 10.7 m across) against the extended skirt (hem 7.47 m; 11 "
     "cells across D0, box 8 D0 wide)", ["T10-m163-w8", "T10-m163-skirt"]),
    ("domainT10Skirt", "T-10 at 163 kg on a guide wire, the extended skirt: "
     "the box's width (11 cells across D0 at the canopy)",
     ["T10-skirt-w5.6", "T10-m163-skirt", "T10-skirt-w11"]),
    ("resolutionT10Skirt", "T-10 at 163 kg on a guide wire, the extended "
     "skirt: cells across D0 at the canopy (box 8 D0 wide)",
     ["T10-skirt-cpd13", "T10-skirt-cpd20", "T10-skirt-cpd30"]),
    ("payloadT10Skirt", "T-10 on a guide wire, the extended skirt: descent "
     "against payload (11 cells across D0, box 8 D0 wide)",
     ["T10-skirt-m100", "T10-m163-skirt", "T10-skirt-m300",
      "T10-skirt-m600"]),
    ("domainT10SkirtLong", "T-10 at 163 kg on a guide wire, the extended "
     "skirt: the box's width in steady descent (13 cells across D0, to 80 "
     "s, read over 50-80 s)",
     ["T10-skirt-cpd13-m163-w5.6", "T10-skirt-cpd13-m163",
      "T10-skirt-cpd13-m163-w11"]),
    ("payloadT10SkirtLong", "T-10 on a guide wire, the extended skirt: "
     "descent against payload in steady descent (13 cells across D0, box 8 "
     "D0 wide, to 80 s, read over 50-80 s)",
     ["T10-skirt-cpd13-m100", "T10-skirt-cpd13-m163", "T10-skirt-cpd13-m300",
      "T10-skirt-cpd13-m600"]),
    ("pressureSolver7ft", "7 ft canopy: the pressure solver's tolerance "
     "(p relTol 0.01 and 0 on the outer iterations; 12 cells across D0)",
     ["7ft-stiff", "7ft-pTight"]),
    ("turbulence7ft", "7 ft canopy: laminar against LES (WALE, LUST "
     "convection; 12 cells across D0)",
     ["7ft-stiff", "7ft-LUST", "7ft-LES"]),
    ("mesh7ft", "7 ft canopy: mesh convergence",
     ["7ft-h0.30", "7ft-h0.20", "7ft-h0.15"]),
    ("duration7ft", "7 ft canopy: is 4 s long enough? (the default run to 8 s, with and without hinge dashpots)",
     ["7ft-h0.20", "7ft-h0.20-8s", "7ft-undamped-h0.20",
      "7ft-undamped-h0.20-8s"]),
    ("porosity7ft", "7 ft canopy: the effect of porosity",
     ["7ft-alpha100", "7ft-h0.20", "7ft-alpha1e4"]),
    ("bending7ft", "7 ft canopy: the hinge dashpots' rate",
     ["7ft-h0.20", "7ft-bend1000", "7ft-bend300", "7ft-bend300-8s",
      "7ft-undamped-h0.20"]),
    ("bendingFilter", "The hinge dashpots' high-pass filter (7 ft and 1/3-scale G-11)",
     ["7ft-h0.20", "7ft-highpass", "7ft-h0.20-8s", "7ft-highpass-8s",
      "G11-flat", "G11-flat-highpass", "G11-folded-deep",
      "G11-folded-deep-highpass"]),
    ("mesh7ftUndamped", "7 ft canopy without hinge dashpots: mesh convergence",
     ["7ft-undamped-h0.30", "7ft-undamped-h0.20", "7ft-undamped-h0.15"]),
    ("porosity7ftUndamped", "7 ft canopy without hinge dashpots: the effect of porosity",
     ["7ft-undamped-alpha100", "7ft-undamped-h0.20", "7ft-undamped-alpha1e4"]),
    ("T10payload", "T-10: terminal velocity against payload",
     ["T10-m100", "T10-m163", "T10-m300", "T10-m600"]),
    ("G11folded", "1/3-scale G-11 from flat and folded starts",
     ["G11-flat", "G11-folded", "G11-folded-deep"]),
    ("G11implicitStructure", "1/3-scale G-11, 4 m fold: the structure in one implicit HHT step per time step, the stabiliser balanced at the step's end (addedMass.balance endOfStep)",
     ["G11-folded-deep", "G11-folded-deep-hht",
      "G11-folded-deep-hht-compress0.1", "G11-folded-deep-hht-relax0.5",
      "G11-folded-deep-hht-compress0.1-relax0.5",
      "G11-folded-deep-hht-relax0.3"]),
    ("G11flatFailure", "1/3-scale G-11 from the flat start: how far it gets",
     ["G11-flat", "G11-flat-relax0.5", "G11-flat-highpass",
      "G11-flat-highpass-relax0.5"]),
    ("crossFolded", "Cross parachute from flat and folded starts",
     ["cross-flat", "cross-folded"]),
    ("compression7ft", "7 ft canopy: the cloth softened in compression",
     ["7ft-h0.20", "7ft-compress0.1", "7ft-h0.20-8s", "7ft-compress0.1-8s"]),
    ("G11compression", "1/3-scale G-11 from flat and folded starts, the cloth softened in compression",
     ["G11-flat", "G11-flat-compress0.1",
      "G11-flat-compress0.1-highpass-relax0.5", "G11-flat-compress0.1-rms",
      "G11-flat-compress0.1-rms-dt0.02",
      "G11-folded-compress0.1", "G11-folded-deep-compress0.1"]),
    ("G11foldedFine", "1/3-scale G-11 from flat and folded starts on the finer mesh (0.475 m cells); the Aitken factor held at 0.3",
     ["G11-flat", "G11-folded", "G11-flat-relax0.3", "G11-flat-h0.475", "G11-folded-h0.475",
      "G11-folded-3.5m-h0.475", "G11-flat-h0.475-relax0.3",
      "G11-folded-h0.475-relax0.3", "G11-folded-3.5m-h0.475-relax0.3"]),
    ("T10payloadCompression", "T-10: terminal velocity against payload, the cloth softened in compression",
     ["T10-m100-compress0.1", "T10-m300-compress0.1",
      "T10-m300-compress0.1-rms", "T10-m600-compress0.1"]),
    ("C9compression", "C-9: the cloth softened in compression",
     ["C9-compress0.1", "C9-compress0.1-rms"]),
    ("G11fullLoad", "1/3-scale G-11 from flat and folded starts with the whole IB reaction as the load (coupling.load.tangential), the stabiliser in every direction and the structure in one HHT step per time step",
     ["G11-folded-deep-hht-relax0.3",
      "G11-folded-deep-hht-relax0.3-tangential",
      "G11-folded-deep-hht-relax0.3-tangential-iso",
      "G11-folded-deep-tangential-iso", "G11-flat-fullLoad",
      "G11-flat-fullLoad-normal", "G11-folded-fullLoad",
      "G11-folded-deep-fullLoad"]),
    ("T10fullLoad", "T-10: terminal velocity against payload with the whole IB reaction as the load",
     ["T10-m100", "T10-m100-fullLoad", "T10-m163-fullLoad",
      "T10-m300-fullLoad", "T10-m600-fullLoad"]),
    ("C9fullLoad", "C-9 with the whole IB reaction as the load",
     ["C9-fullLoad"]),
    ("G11meshFullLoad", "1/3-scale G-11: mesh convergence with the whole IB reaction as the load",
     ["G11-flat-fullLoad", "G11-flat-h0.7125-fullLoad",
      "G11-flat-h0.475-fullLoad", "G11-folded-fullLoad",
      "G11-folded-h0.475-fullLoad"]),
    ("mesh7ftFullLoad", "7 ft canopy: mesh convergence with the whole IB reaction as the load",
     ["7ft-h0.30-fullLoad", "7ft-h0.20-fullLoad", "7ft-h0.15-fullLoad",
      "7ft-h0.10-fullLoad", "7ft-h0.20-fullLoad-16s",
      "7ft-h0.15-fullLoad-16s"]),
]
