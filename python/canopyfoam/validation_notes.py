"""validation_notes.py — the validation report's hand-written prose: each study's findings and the design notes every report keeps."""


# What the 7 ft canopy's mapped levels show (study resolution7ftMapped)
MAPPED_7FT_PROSE = [
    "How the levels start: 7ft-cpd18-cloth0.044-10s inflates the 0.044 m "
    "cloth from rest on 18 cells (14 min on 2 ranks); each level then "
    "meshes the same domain at its resolution, maps the source's U and p "
    "at 10 s onto it (`canopy-run-case -mapFieldsFrom`, OpenFOAM's "
    "mapFields -consistent), places the source's canopy at rest in the "
    "frame (rest_state.py) and gives every node the payload's last "
    "velocity (5.600 m/s). On 18 cells, the source's own mesh, the mapped "
    "fields are the source's bit for bit (tests/openfoam/mapFieldsStart) "
    "and the descent goes on at 5.5-6.0 m/s with no start transient. On "
    "40 cells it goes on at 5.8-5.95 m/s for 2.5 s, then falls to 5.6-5.7 "
    "m/s over 3-4 s. On 27 cells it falls to 4.4 m/s "
    "within 0.5 s, the canopy opening to 0.85 D0, and is back at 5.8 m/s "
    "by 2.25 s; the same start with half the time step "
    "(7ft-mapped-cpd27-co0.25, study timeStep7ftMapped) follows it to "
    "within 0.2 m/s (4.3-4.8 m/s over 0.25-1.1 s) until it stopped at "
    "1.14 s, so the dip is the start on that mesh, not chance. The "
    "levels are therefore "
    "also read over 2-4 s (the second table), and the converged value is "
    "taken over that window (`bin/canopy-validate converged "
    "resolution7ftMapped`, CONVERGED_WINDOWS).", "",
    "Over 2-4 s the three levels agree within their intervals: C_D0 0.810, "
    "0.776 and 0.793 at 18, 27 and 40 cells across D0 (± 1.9-3.8 %), "
    "C_Dp 1.33, 1.30 and 1.31, Dp/D0 0.78 at every level. The changes "
    "oscillate inside the windows' scatter, so Roache's GCI is the "
    "oscillatory bound: 13.4 % in C_D0, 6.8 % in the descent, 3.4 % in "
    "C_Dp, 5.0 % in Dp/D0. With the finest cloth the air's resolution "
    "from 18 to 40 cells across D0 moves the drag less than a 2-3 s "
    "window can tell; what moved the 7 ft canopy's drag in the earlier "
    "studies was the cloth (edgeLength7ftCpd27: 0.712, 0.782, 0.813 for "
    "the 0.099, 0.066 and 0.044 m edges at 27 cells, from rest, 8-12 s). "
    "The same cloth from rest at 27 cells (7ft-cpd27-edge0.56) gave "
    "0.813 ± 3.1 % over 8-12 s, 2.5 % above the 40-cell level here.", "",
    "The breathing is the one quantity that moves with the air's "
    "resolution: 1.13, 1.28 and 1.49 Hz (amplitude 19.6, 15.2 and 7.0 "
    "cm of the projected diameter) at 18, 27 and 40 cells over 1-4 s, "
    "Strouhal number f Dp / V 0.33, 0.38 and 0.43, rising towards the "
    "drop test's visible 2 Hz (Kim 2012, sec. 5.7) and not converged "
    "(3-4.5 periods a window).", "",
    "Against published values: C_D0 0.79 ± 13 % lies in the handbook's "
    "0.75-0.80 for solid flat circular canopies (Knacke, NWC TP 6575, "
    "Table 5-1; 5.7-5.9 m/s for the model's 5.70 kg), while the canopy "
    "stays more open than the handbook's Dp/D0 0.67-0.70 (0.78). The "
    "drop test's 4.27 m/s (C_D0 about 1.35) stays beyond it. The tutorial "
    "(18 cells, the 0.148 m edge) gives 0.685 over 8-12 s and 0.674 over "
    "10-40 s, 14-15 % below this level: its error is the cloth's "
    "resolution more than the air's. Each 7 ft run's summary compared "
    "with this study (report.py, convergedStudy) until the study on the "
    "tutorial as it is (resolution7ftCells, section \"The 7 ft canopy's "
    "resolution on the tutorial\") took its place; its caveat: "
    "the window is 2 s right after a 10 s state, and from rest the "
    "descent drifts for tens of seconds.", "",
    "Cost: 40 cells across D0 on the narrow refinement is 855 876 cells; "
    "4 s took 42 min on 2 ranks at 1.01 coupling iterations a step (1.13 "
    "at 27 cells, 1.41 at 18), against about 10 h from rest on the "
    "tutorial's refinement (7ft-cpd40-held).", ""]


# What the T-10's mapped levels show (study resolutionT10Mapped)
T10_KERNEL_PROSE = [
    "Against the same levels on the load from the cells with the "
    "stabiliser's balance of each triangle's plain mean (T10-mapped-cpd13-"
    "cells and T10-mapped-cpd20-cells, study cellReactionT10, made on "
    "the code of 579aea4 and bff5525), the kernel's "
    "balance gives the same descent (6.144 against 6.142 m/s at 13 cells, "
    "6.401 against 6.404 at 20; C_D0 0.8125 against 0.8130 and 0.7484 "
    "against 0.7478) in fewer coupling iterations over the whole run "
    "(1.14 against 1.37 a step at 13 cells, 1.18 against 1.41 at 20; at "
    "most 6 and 9). So the 7 ft tutorial's coupling carries over to the "
    "T-10 unchanged in its answer. The T-10's C_D0 falls with the air's "
    "resolution on every coupling tried (on each marker's own force 0.832, "
    "0.743 and 0.680 at 13, 20 and 30 cells, study resolutionT10Mapped), "
    "and on this coupling the 30-cell level (T10-mapped-cpd30-kernel, 707 "
    "800 cells, 25 minutes on 2 ranks, partly beside a test run) gives "
    "6.59 ± 0.12 m/s over 2-12 s, C_D0 0.707, Dp/D0 0.761, at 1.21 "
    "coupling iterations a step (1.00 in the steady interval, at most "
    "11); its descent still falls across the window (6.87 m/s over 2-3 s, "
    "6.40 over 11-12 s, a drift of -0.37 against ±0.12), so its 2-12 s "
    "mean is not yet a steady one. The three levels converge "
    "monotonically (0.8125, 0.7484, "
    "0.7066): Roache's GCI of the 30-cell level is 17.4 % in C_D0 "
    "(extrapolated 0.608), 12.3 % in the descent (extrapolated 7.24 m/s) "
    "and 3.6 % in C_Dp (1.219). The 30-cell level continues the source "
    "re-made on the current coupling, the 13- and 20-cell levels the "
    "earlier run (C_D0 0.779 against 0.789 over 50-80 s, inside their "
    "intervals). The T-10's published 22 ft/s (6.7 m/s) at 163 kg, C_D0 "
    "0.66 (section of study resolutionT10Mapped), lies inside the GCI: "
    "the finest level is 7 % above it and the extrapolation 8 % below.",
    ""]

MAPPED_CELLS_7FT_PROSE = [
    "All three levels ran on the stabiliser's balance seen through the "
    "kernel, where the balance of each triangle's plain mean had stalled "
    "their second step: 1.12, 1.17 and 1.07 coupling iterations a step "
    "over the whole run (at most 5, 10 and 4), 6, 35 and 59 min on 2 "
    "ranks (the 27-cell level shared the cores with other runs).", "",
    "C_D0 0.817, 0.899 and 0.793 at 18, 27 and 40 cells across D0 differ "
    "by more than the levels' intervals, which are those of a 3 s window "
    "and do not cover the descent's slower wander (on the main job's "
    "set-up its 2 s means range over 5.36-5.54 m/s over 10-40 s, about "
    "±3 % in C_D0, 7ft-default-40s). The 27-cell level's start was the "
    "roughest: its descent fell to 4.18 m/s at 0.5-0.75 s after the mapping and came "
    "back to 5.4 m/s only from 2.25 s, so its window reads the end of "
    "that transient; the 18-cell level still rises across its window "
    "(+0.14 m/s). So this study does not bound the air's resolution error "
    "(GCI 83 %); the study from rest over 10-15 s (resolution7ftCells) "
    "does. On each marker's own force the same levels gave C_D0 0.803, "
    "0.837 and 0.777 (study resolution7ftMapped): the load from the cells "
    "raises them by 1.8, 7.4 and 2.1 %.", "",
    "The fine cloth breathes at every level, 1.33, 1.25 and 1.37 Hz with "
    "3.4, 7.6 and 7.5 cm (St about 0.4), with the tutorial's hinge "
    "dashpots on: on the 0.044 m cloth they damp a smooth bending about "
    "130 times less than on the main job's 0.148 m cloth (section \"The "
    "7 ft canopy's breathing against the cloth's edge and the hinge "
    "dashpots\"). The 40-cell level's 1.37 Hz is within 0.02 Hz of the "
    "main job's set-up without dashpots (7ft-default-bend0-15s, 1.39 Hz).",
    ""]

MAPPED_T10_PROSE = [
    "The 13- and 20-cell levels were re-made with the current code for "
    "study markersT10 (their records are the re-made runs): 6.085 ± 0.022 "
    "and 6.473 ± 0.017 m/s, C_D0 0.828 and 0.732, where as first made "
    "(code bff5525) they gave 6.07 and 6.43 m/s, C_D0 0.832 and 0.743. "
    "With the 30-cell level as made (code 830564e, continued with "
    "1fc4445) the levels fall by 11.6 % and 7.1 % and converge "
    "monotonically with an observed order of about 1.5: C_D0 0.680 ± "
    "13.2 % (GCI), extrapolated 0.609, the descent 6.71 m/s ± 9.1 % (the "
    "table above). The paragraphs below are of the levels as first made "
    "(GCI 34.7 %, order 0.7).", "",
    "All three levels run the tutorial's stabiliser (each triangle's mean "
    "acceleration, balanced from zero each step) with the coupling's "
    "residual over its whole iterate (section \"The coupling's residual "
    "over its whole iterate\"). Before, on the earlier stabiliser (lumped, "
    "from the last step's acceleration) with the residual of the normal "
    "velocity alone, the three levels gave 6.072, 6.474 and 6.69 m/s, "
    "C_D0 0.832, 0.732 and 0.686 (GCI 8.5 %, extrapolated 0.639) at 2.9, "
    "3.5 and 4.4 iterations a step.", "",
    "The source, 13 cells across D0 with the 0.446 m cloth (1072 "
    "triangles; the tutorial's 1.03 m edge), descended at 6.24 ± 0.19 "
    "m/s over 50-80 s (C_D0 0.789, Dp/D0 0.76) when the levels here "
    "continued its 80 s state, against 6.67 m/s (C_D0 0.690) with the "
    "tutorial's cloth at the same resolution (T10-skirt-cpd13-m163): as "
    "on the 7 ft canopy, the finer cloth drags more. Re-made with the "
    "current coupling (for the 30-cell level of study "
    "resolutionT10Kernel; its record is the re-made run) it descends at "
    "6.28 ± 0.07 m/s (C_D0 0.779, Dp/D0 0.757) at 2.52 coupling "
    "iterations a step against 3.22, in 8.4 minutes on 2 ranks against "
    "12.7: within the earlier run's interval. The mapped levels start "
    "without a transient beyond their first "
    "second (the table of 1 s means). From 13 to 20 cells across D0 C_D0 "
    "falls by 10.7 %, beyond the two runs' intervals, and the breathing "
    "peak goes from 0.18 Hz to 0.21 Hz (periods of 5.5 and 4.8 s, about "
    "two of them in each 10 s window; the seed's measured T-10 breathing "
    "period is 2.3 s, Kim 2012, sec. 5.7).", "",
    "At 30 cells across D0 (707 800 cells, about 40 min on 2 ranks) the "
    "descent is 6.714 ± 0.040 m/s, C_D0 0.680: from 13 to 20 cells C_D0 "
    "falls by 10.7 %, from 20 to 30 by 8.5 %, each beyond the pair's "
    "intervals. The levels converge monotonically but slowly (observed "
    "order about 0.7, below the IB delta function's formal order 1), so "
    "Roache's GCI of the finest level is wide: C_D0 0.680 ± 34.7 %, "
    "extrapolated 0.49; the descent 6.71 m/s ± 25.8 %. The projected "
    "diameter does not converge (Dp/D0 0.765, 0.751, 0.765, oscillating "
    "within 0.015 D0), so C_Dp diverges. The 30-cell level shows no "
    "breathing peak over 2-12 s (its largest is in the spectrum's first "
    "bin, 1.3 cm), so neither the 13- and 20-cell levels' 0.18-0.21 Hz "
    "nor the earlier coupling's 0.42 Hz at 20 cells is converged. The "
    "coupling takes 1.49, 1.50 and 1.39 iterations a step at 13, 20 and "
    "30 cells (1.06 in the 30-cell level's steady interval, at most 12): "
    "the target of at most 2 a step at the finest level is met for the "
    "T-10.", "",
    "Against published values: the T-10's average descent of 22 ft/s "
    "(6.7 m/s) with at most 163 kg (Mills Manufacturing; 19-23 ft/s by "
    "the jumper's weight and the air's density, globalsecurity.org) is "
    "C_D0 0.66 at 163 kg and sea level; the finest level's 0.680 and "
    "6.71 m/s are within 3 % of it, but the levels have not converged "
    "(± 34.7 %; their extrapolation, 0.49, is below every parachute of "
    "this class, so the observed order is not yet the asymptotic one and "
    "a 45-cell level is needed). The inflated diameter 25.7 ft (Dp/D0 "
    "0.73) is 5 % below the model's 0.765. The tutorial's "
    "cloth (1.03 m edge) at 13 cells gives 0.690 at 163 kg over 50-80 s "
    "(T10-skirt-cpd13-m163), 1.4 % from the finest level's: at 13 cells "
    "the coarser cloth's lower drag and the coarser air's higher drag "
    "cancel (study edgeLengthT10), so each T-10 run's summary compares "
    "with this study (report.py, convergedStudy).", ""]


# What the T-10's fabric edge does at 13 cells (study edgeLengthT10)
EDGE_T10_PROSE = [
    "At 13 cells across D0, from rest to 80 s and read over 50-80 s, the "
    "tutorial's 1.03 m edge gives C_D0 0.690, the 0.683 m edge 0.815 "
    "(+18 %, beyond the pair's interval) and the 0.446 m edge 0.789 (-3 "
    "%, inside the pair's interval: the 0.446 m run's descent scatters by "
    "± 0.19 m/s over the window; re-made with the current coupling, "
    "0.779 ± 2.3 %, the table's row). As on the 7 ft canopy, refining the "
    "cloth from the tutorial's edge raises the drag, and below 0.83 "
    "finest cells the change is within the runs' scatter. The projected "
    "diameter does not move (Dp/D0 0.757, 0.755, 0.762). At 30 cells "
    "with the 0.446 m cloth the air's refinement takes C_D0 back down to "
    "0.680 (study resolutionT10Mapped): the tutorial's 0.690 at 13 cells "
    "is that converged value by a cancellation of the cloth's error "
    "(0.690 against 0.789-0.815 with the finer cloths at 13 cells, about "
    "-15 %) and the air's (0.789 at 13 cells against 0.680 at 30 with the "
    "0.446 m cloth, +15 %), not by resolving either. The tutorial's "
    "cloth (T10-skirt-cpd13-m163) was re-made with the current code for "
    "study markersT10Tutorial: C_D0 0.675 (6.74 ± 0.21 m/s, Dp/D0 0.768), "
    "inside its first run's interval; the table's row is the re-made "
    "run, the figures above its first.", ""]


# What the T-10's coupling variants show (study couplingT10)
COUPLING_T10_PROSE = [
    "T10-mapped-cpd13 and T10-mapped-cpd20 are the tutorial as it is now: "
    "its stabiliser balanced as the 7 ft's (each triangle's mean "
    "acceleration, from zero each step) and the coupling's residual over "
    "the whole iterate, 1.49 and 1.50 iterations a step (section \"The "
    "coupling's residual over its whole iterate\"). The other runs here, "
    "and the figures in the rest of this paragraph, are of the tutorial's "
    "earlier stabiliser (lumped, from the last step's acceleration) with "
    "the residual of the normal velocity alone, which took 2.92 and 3.50 "
    "a step at 13 and 20 cells.", "",
    "At 13 cells across D0 the stabiliser's triangle-mean filter (the 7 "
    "ft tutorial's) leaves the coupling at 2.91 iterations a step against "
    "2.92, and IQN-ILS in place of Aitken's relaxation takes it to 2.06 "
    "(at most 8), with the same descent (6.073 against 6.072 m/s, C_D0 "
    "0.8316 against 0.8317) in 78 s instead of 102. At 20 cells IQN-ILS "
    "gives 3.34 a step against Aitken's 3.50 (6.459 against 6.474 m/s, "
    "C_D0 +0.5 %, inside the runs' intervals): the count's growth with the "
    "resolution (2.9, 3.5, 4.4 at 13, 20, 30 cells) is not the relaxation's "
    "doing, nor the filter's, and neither meets the target of 2 a step at "
    "the finest level. The stabiliser's balance is what takes the "
    "iterations: started from zero each step (predictor zero, the 7 ft "
    "tutorial's) instead of from the last step's acceleration, the "
    "coupling ended each step at its first iteration, 1.00 a step at 13 "
    "and at 20 cells (102 s to 36 s and 7.0 to 2.1 min), with the same "
    "steady "
    "descent within the intervals (6.078 against 6.072 m/s at 13 cells; "
    "6.429 against 6.474 at 20, C_D0 +1.4 %, Dp/D0 0.751 against 0.748). "
    "It does change the breathing: at 20 cells 0.19 Hz and 3.0 cm against "
    "0.42 Hz and 11.1 cm. Ended at the first iteration, the balance "
    "stayed zero and the stabiliser's 2.7 kg/m^2 acted as the cloth's "
    "inertia, 72 times the nylon's: the residual of the normal velocity "
    "alone did not see it, which is why the residual now covers the "
    "balance.", ""]


# What halving the T-10's time step shows (study timeStepT10Mapped)
TIME_STEP_T10_PROSE = [
    "Halving the Courant number at 20 cells across D0 (1023 steps "
    "instead of 514 over 12 s) moves the descent from 6.474 to 6.478 m/s "
    "(+0.004 ± 0.07) and C_D0 from 0.732 to 0.731 (-0.1 %), Dp/D0 from "
    "0.748 to 0.753; the breathing peak stays at 0.42-0.44 Hz (its "
    "amplitude 11.1 and 4.7 cm). Both runs are of the earlier coupling "
    "(the lumped stabiliser from the last step's acceleration, the "
    "residual of the normal velocity); on it the time step's error was "
    "far below the resolution's (GCI 8.5 % in C_D0 then, 34.7 % now, "
    "study resolutionT10Mapped). The "
    "coupling takes more iterations at the shorter step (4.5 a step "
    "against 3.5), so a shorter step does not bring the T-10's count "
    "towards the target of 2 (study couplingT10 finds what does).", ""]


# The design notes of the strong coupling (measurements behind what the
# coupling headers describe), written by hand, kept in every report
COUPLING_NOTES = ["## Coupling design notes", ""]
COUPLING_NOTES += [
    'Why the strong coupling is built as it is (canopyCoupling.H and '
    "the parts' headers describe what the code does).", ""]
COUPLING_NOTES += [
    "The stabiliser's balance and the no-slip velocity are the "
    "interface acceleration's secondary data, moved by IQN-ILS with "
    "its columns. Without that, the stabiliser's lag (m_A/(m + m_A) = "
    '0.94 of the last output carried into the next solve) made '
    'IQN-ILS fail within one time step of the 7 ft canopy.', ""]
COUPLING_NOTES += [
    'With the stabiliser the structure solve already relaxes. In a '
    "one-mode model (the air's load −M (v − v_0)/dt, one HHT step "
    'with γ = 1/2 − α = 0.8, balanced at its end) a mode whose added '
    'mass per area is M converges by (m_A − γM)/(m + m_A) per plain '
    'iteration, inside (−1, 1) wherever γM < 2 m_A + m: M < 1.4 kg/m² '
    "for the 7 ft canopy's m_A = 0.54, above a broadside disc's 0.85 "
    'ρR = 1.09. A first Aitken factor below 1 then only slows the '
    'iteration: from 0.3, the residual grew after 40 % of the updates '
    "with a factor below 1 (12, 18 and 27 cells across D0), Aitken's "
    'factor turned negative and restarted from 0.3, and the 7 ft '
    'canopy needed 4.1-4.5 coupling iterations a step in steady '
    'descent; from 1 it needed 2.0-2.6 (study relaxation7ft above; '
    'tutorials/parachutes/flatCircular7ft/README.md).', ""]
COUPLING_NOTES += [
    "### IQN-ILS when the past steps mislead it", "",
    "At the coupling's tolerance 2.5e-3 the 7 ft tutorial stopped while "
    "its canopy inflated (7ft-cpd12-markerhalf-tol2.5e-3-40s at 0.89 s; "
    "tests/openfoam/inflationTolerance at 0.52 s): IQN-ILS, fitted to "
    "the columns of the last 8 steps (72 columns, the inflation taking "
    "8-10 iterations a step), made an update that raised the residual "
    "from 0.028 to 0.68 (the slip to 1.0 m/s), and the iteration stayed "
    "above 0.05 for 20 iterations. The past steps' columns describe the "
    "map as it was; while the canopy inflates it changes from step to "
    "step. IQN-ILS now drops them when an iteration's residual exceeds "
    "its step's first, since the model's update then did worse than no "
    "update, and goes on with the step's own columns, which include the "
    "secant of that bad update. From the stopped run's last good state "
    "the failing step then converged, and from rest the run went to 40 "
    "s (three drops, at 0.64 and 2.09 s; study numerics7ftMarkerHalf). "
    "In steady descent the residual falls every iteration: over the "
    "main job's 4 297 steps and the 18- and 27-cell levels' no "
    "iteration's residual exceeded its step's first, so the drop leaves "
    "them as they were, bit for bit (the main job re-run by the "
    "benchmark, 7ft-cpd12-markerhalf-co0.25-40s and -tol1e-2-40s re-made "
    "with it: the same records but for the wall time). On a linear map changed between steps (Test-interfaceAcceleration, "
    "check 11) the drop costs evaluations, 27 against 9 with the stale "
    "columns kept (on a linear map the newest columns correct them), "
    "and that cost is bounded: the step converges within n + 2 "
    "evaluations of the drop.", ""]
COUPLING_NOTES += [
    "### The stabiliser's balance under Aitken's relaxation", "",
    "Aitken's relaxation moves the secondary data with its factor, as it "
    "moves the interface velocity. It used to hand them the last "
    "solve's values. The stabiliser's balance then formed a loop of its "
    "own that the factor does not reach. In the model of the stabilised "
    "coupling (tests/openfoam/interfaceAcceleration: G(x, s) = x* + "
    "A (x − x*) + ρ (s − x*), ρ = m_A/(m + m_A) = 0.935 for the 7 ft "
    "canopy), one mode whose pair gain A + ρ is λ converges per "
    "iteration by:", "",
    "- with the balance handed on: the spectral radius of "
    "[[1 − ω + ωa, ωρ], [a, ρ]] (a = λ − ρ, the mode's gain of A): 0.68 at ω = 0.5 and 0.92-0.94 "
    "at the factors 0.05-0.1 that Aitken falls to, for every λ from "
    "−0.6 to −2;",
    "- with the balance relaxed with x: |1 + ω (λ − 1)|, e.g. 0.25 at "
    "λ = −1.5 and ω = 0.3-0.5.", "",
    "Check 8 of that test: Aitken from the tutorials' factor 1 (floor "
    "0.05), pair gains down to −1.6. It converges in 28 evaluations "
    "with the balance relaxed; it has not after 200 with the balance "
    "handed on.", "",
    "The 7 ft main job in a 5.6 D0 box (`7ft-default-w5.6`) showed it. "
    "It stopped at 0.31 s while inflating: with 20 and with 40 "
    "iterations its residual alternated between 0.0054 and 0.0060 "
    "against the tolerance 0.005, with Aitken's factor at its floor "
    "0.05. Relaxing the balance alone (the no-slip velocity still "
    "handed on) carried it through, as does relaxing both (the code). "
    "It takes 5-6 iterations a step at 0.3 s, and the whole run 1.29 "
    "iterations a step (study domain7ft). IQN-ILS (`initial 1; reuse 8; "
    "filter 1e-3`) is no cure here: it stopped earlier, at 0.29 s, its "
    "residual at 0.016-0.024 through 20 iterations.", "",
    "A step that ends unconverged and goes on (`stopIfNotConverged "
    "false`) hands the next step the committed structure's velocities "
    "and the last solve's balance, as a restart would, not the relaxed "
    "iterate. Handing on the relaxed no-slip velocity in the ground "
    "frame only (the payload frame re-reads the structure at each "
    "step's start) made the two frames of tests/openfoam/frameGalilean "
    "differ by 3.7e-6 after three steps; they now agree to 7e-13.", ""]
COUPLING_NOTES += [
    "### The coupling's two-cycle: the markers relaxed with the iterate",
    "",
    "The markers' positions and normals are secondary data of the "
    "interface acceleration too, relaxed with the iterate "
    "(interfaceIterate.H). They used to sit on each structure solve's "
    "result. The fluid reads them: the IB forcing acts where they are, "
    "and the cloth's pressure jump is sampled at x ± δn from them. So "
    "they formed a loop outside the factor, as the stabiliser's balance "
    "did.", "",
    "`7ft-default-w5.6-40s` (study domain7ftLong) showed it. The run "
    "stopped at 30.92 s: Aitken's factor fell from 1 to its floor 0.05 "
    "within six iterations. The residual then alternated between 0.0055 "
    "and 0.011 for 20 iterations, with its largest change on the same "
    "triangle, whose centre moved back and forth by 3 mm, while the "
    "cloth's lateral load swung by about 1 N. A factor of 0.05 moves the "
    "interface velocity by 5 % of the residual, so only a part of the "
    "state that the factor does not reach can carry a two-cycle of "
    "constant size.", "",
    "Restarted from the last good state (30.9148 s) with the markers "
    "relaxed, the step converges in 3 iterations. The next five steps "
    "take 9, 3, 5, 4 and 2. The positions are relaxed in the mesh's "
    "frame, as the velocities. The first iteration's held positions are "
    "then the step's start carried with the frame. Relaxed in the "
    "ground frame instead, the first iterate lags the frame by (1 − ω) "
    "V Δt: the two frames of tests/openfoam/frameGalilean then differed "
    "by 3.9e-3, where they agree to 2.2e-12 in the mesh's frame.", "",
    "Elsewhere: tests/openfoam/lightCanopyStability took 5.07 "
    "iterations a step (at most 7) against 5.17 before (5.02 with the "
    "areas relaxed too, below). With 4 forcing "
    "iterations it took 6.33 (at most 10) against 6.25; both run to "
    "0.4 s. IQN-ILS (`initial 1; reuse 8; filter 1e-3`) is no cure at "
    "the 5.6 D0 state. Before the change it passed 30.95 s with up to "
    "18 iterations a step. With the markers relaxed it stops at "
    "30.943 s (residual 0.16 after 20 iterations). No tutorial uses "
    "it.", "",
    "What moved. The change acts only on steps that take more than one "
    "iteration, so the converged answer stays; a run's course and its "
    "window means move within their scatter. 7ft-default: 6.11 ± 0.07 "
    "m/s and C_D0 0.698 over 8-12 s, 1.35 iterations a step (at most "
    "14), where it gave 6.33 ± 0.09 m/s, 0.651 and 1.30 (at most 6). "
    "7ft-default-40s over 10-40 s: 6.31 ± 0.10 m/s, C_D0 0.654, 1.22 "
    "iterations a step (at most 14), where it gave 6.19 ± 0.10, 0.679 "
    "and 1.14 (at most 10); the descent moved by 0.12 m/s, inside the "
    "two runs' combined interval of ±0.14.", ""]
COUPLING_NOTES += [
    "### The coupling's two-cycle: the markers' areas",
    "",
    "With the markers' positions and normals relaxed, "
    "7ft-default-bend1000 (the main job with the hinge dashpots at "
    "1000 /s) still stopped at 4.076 s. Aitken's factor fell to its floor "
    "of 0.05 at the second iteration, and the residual then alternated "
    "between 0.0056 and 0.0094 for 20 iterations (tolerance 0.005). Its "
    "largest change switched between two skirt nodes 3 mm apart, while "
    "the load on the cloth swung by about 0.6 N sideways and 1 N along "
    "the axis from one iteration to the next. Restarted from the run's "
    "regular write at 4 s the stop repeats to ten digits, so this state "
    "reproduces the two-cycle in five minutes on 2 ranks.", "",
    "Three runs of the failing step from a regular write at its start "
    "(4.0707 s; a write interval of one time step keeps the run's steps) "
    "found the carrier. With `coupling.restartFluid true` the fluid is "
    "solved from the step's start in every iteration, and the residual "
    "alternated the same way (0.0055-0.0095): the fluid's own state (U, "
    "p, phi) is not it. With Aitken's factor held at 1e-6 the iterate "
    "cannot move, yet the residual still alternated (0.0102, 0.0053, "
    "0.0118, 0.0053, ...), with the fluid restarted or not: something "
    "outside the iterate changed the answer. That was the markers' "
    "areas. The markers move to the relaxed positions and normals, but "
    "each structure solve's placement left them its triangles' areas, "
    "and the areas enter the fluid twice: as the forcing's marker "
    "volumes and in the load per area. The areas are now relaxed with "
    "the iterate as well (interfaceIterate.H; the acceleration moves "
    "scalar secondary data with the vector data, "
    "tests/openfoam/interfaceAcceleration). With the factor held at "
    "1e-6 the residual is then the same in every iteration (0.0024008 "
    "in iterations 5-8). With the tutorial's settings the failing step "
    "converges in 3 iterations (0.0080, 0.0072, 0.0024), and the run goes "
    "on through 4.2 s at no more than 5 iterations a step. Re-made from "
    "rest, 7ft-default-bend1000 runs to 12 s at 1.40 iterations a step "
    "(at most 10; study hingeDamping7ft).", "",
    "What moved. 7ft-default: 6.17 ± 0.03 m/s and C_D0 0.685 over "
    "8-12 s, 1.32 iterations a step (at most 7), where it gave 6.11 ± "
    "0.07, 0.698 and 1.35 (at most 14). 7ft-default-40s over 10-40 s: "
    "6.22 ± 0.04 m/s, C_D0 0.674, 1.18 iterations a step (at most 7), "
    "where it gave 6.31 ± 0.10, 0.654 and 1.22 (at most 14). The largest "
    "count of iterations in a step halved, and the 10-40 s interval "
    "narrowed from ±0.10 to ±0.04 m/s (11.5 independent samples "
    "instead of 6.3).", "",
    "### The last good state's loads",
    "",
    "A step that fails writes the state it started from, the last good "
    "state. libcanopy's checkpoint held the time, positions, velocities "
    "and carried acceleration, but not the loads set on the model. So "
    "after a failed strong-coupling step the written structure state "
    "carried the last iterate's pressure jump and nodal forces: in the "
    "run above the pressure jump reached 2.1e5 Pa, against 8.4e3 at the "
    "step's start. A restart reads them back (restart.c). It took another "
    "path: its first iteration's residual was 0.0141 where the run had "
    "0.0080, and it went on past 4.08 s. Written with the step start's "
    "loads, the same state repeats the stop. Checkpoint and restore now "
    "include the pressure jump and the nodal forces "
    "(tests/canopy/test_checkpoint.c, restore_returns_loads: the old "
    "code repeats a restored step only to 1.3e-4). A restart from a last "
    "good state therefore goes on as the run would have.", ""]


# What stopped the long 7 ft runs (study tolerance7ftLong) and the cure,
# measured by restarting them from their written states (27 s, 28 s, 32 s)
DIVERGENCE_NOTES = ["## The long 7 ft runs' stop: a suspension line's "
                    "vibration, cured by resolving the lines in the "
                    "structure's step", ""]
DIVERGENCE_NOTES += [
    "Both long runs of study tolerance7ftLong stopped with the "
    "structure's HHT step diverging (a node above the 100 m/s speed "
    "limit): `7ft-tol1e-3-relax1-40s` at 27.30 s, `7ft-relax1-40s` at "
    "37.66 s. The stop is deterministic (a restart from 27 s stops at "
    "27.2963 s, node 255 at 104.935 m/s, the same digits). The canopy "
    "file (postProcessing/canopy/canopy.h5, every 0.25 s) shows where it "
    "starts: one suspension line (nodes 254-263 between skirt node 109 "
    "and the payload) vibrates across its length. Its largest speed "
    "relative to the payload is 0.1-0.4 m/s while the wake is "
    "symmetric, then grows within about a second to 20 m/s (from 19.5 s "
    "in the 1e-3 run, from 32.5 s in the 5e-3 run) and stays at 15-80 "
    "m/s for 5-7 s, its segments stretched by up to 3 % (tensions of "
    "tens of N where the payload's weight gives each line 3.3 N), until "
    "a node passes the limit. The cloth moves at 0.2-2 m/s relative to "
    "the payload meanwhile; the load oscillation of 22-152 N at 35 Hz "
    "and the 8-35 coupling iterations a step before the stop are the "
    "whipping line pulling the skirt. So the descent these runs read "
    "after 19.5 s (1e-3) and 32.5 s (5e-3) carries a line that no real "
    "parachute has.", "",
    "The structure took one implicit HHT step per fluid time step "
    "(`maxOmegaDt 1e9`): Lambda dt about 40 for the lines' "
    "axial modes (the frequency bound Lambda is about 7000 rad/s: a 0.97 g "
    "node between two 0.194 m segments of EA 1923 N). HHT-alpha is "
    "unconditionally stable for linear problems only; in nonlinear "
    "dynamics with a very stiff and a very flexible response together "
    "(here the lines' axial stiffness and their transverse motion) the "
    "trapezoidal family can go unstable (K.-J. Bathe and G. Noh, "
    "Computers & Structures 98-99, 2012, 1-6; Bathe and Baig, Computers "
    "& Structures 83, 2005, 2513-2524). Restarts of `7ft-relax1-40s` "
    "from 32 s, when its line already moved at 4 m/s, to 34 s with one "
    "change each (largest line speed at 33.5 s; about a minute each):", "",
    "| change | sub-steps a step | line speed at 33.5 s [m/s] | end |",
    "|---|---|---|---|",
    "| none (one HHT step, Lambda dt about 40) | 1 | 35.5 | 34 s |",
    "| maxOmegaDt 20 | 4 | 76 at 33.2 s | diverged at 33.21 s |",
    "| maxOmegaDt 10 | 7 | 92 at 32.37 s | diverged at 32.38 s |",
    "| maxOmegaDt 4 | 17 | 4.0 | 34 s, 2.0-4.7 throughout |",
    "| maxOmegaDt 2 | 33 | 4.1 | 34 s, 3.0-5.3 throughout |",
    "| maxOmegaDt 1 | 65 | 3.5 | 34 s, 2.8-4.3 throughout |",
    "| hhtAlpha 0 (no numerical damping) | 1 | - | diverged at 32.33 s |",
    "| Newton tolerance 1e-9 instead of 1e-5 | 1 | 17.5 | 34 s, 32 m/s at its end |",
    "| lines' axial damping 0.3 N s/m (about 5 % of critical) instead of 0.05 | 1 | 24.7 | 34 s |",
    "| no hinge dashpots | 1 | 36.2 | 34 s, 6.6 coupling iterations a step |", "",
    "Resolving the lines' axial modes (Lambda dt <= 4) is what stops the "
    "growth; damping does not. Restarted from 28 s (its line at 1.3 m/s) "
    "with `maxOmegaDt 2`, `7ft-relax1-40s` runs to 40 s with the line at "
    "0.8-3.1 m/s throughout. The HHT tutorials (7 ft, T-10, C-9, both "
    "1/3-scale G-11) therefore take sub-steps of Lambda dt <= 2 "
    "(`integrator.maxOmegaDt 2`, about 33 a time step in the 7 ft case); "
    "the structure's share of the wall time does not grow (10.4 s against "
    "14.6 s of the 2 s restart: the sub-steps' Newton solves converge in "
    "fewer iterations than the one large step's). The coupling needs "
    "more iterations: the added-mass stabiliser is balanced by the last "
    "sub-step's end acceleration (`addedMass.balance endOfStep`), which "
    "cancels its mass term exactly only in one step. The 7 ft case at 8 "
    "cells across D0 to 2 s (tests/foamRun/flatCircular7ft) takes 4.3 "
    "iterations a step instead of 2.2 (descent at 2 s 3.262 m/s instead "
    "of 3.247; 4.4 with 17 sub-steps, `maxOmegaDt 4`). Balanced by the "
    "step's mean acceleration (`stepMean`) instead, the sub-stepped "
    "coupling does not converge while the canopy inflates (20 iterations "
    "at 0.19 s). The extra iterations are in the step's first one: its "
    "interface residual is 0.025-0.03 instead of 0.004-0.005 (8 cells, "
    "1.5 s), while each further iteration reduces it by about 0.3 as "
    "before. The first iteration balances with the previous step's "
    "balance, the last sub-step's acceleration, which carries the fast "
    "modes the sub-steps now resolve at that instant. Started instead "
    "from the previous step's mean acceleration (`addedMass.predictor "
    "lastStepMean`, later iterations still balanced by the end "
    "acceleration), the coupling takes 3.0 iterations a step over 0-2 s "
    "at 8 cells (2.2 after 1 s; descent at 2 s 3.300 m/s), 2.18 instead "
    "of 2.42 from the restart at 32 s above (5e-3), and 2.27 instead of "
    "3.51 over 30-32 s of the re-made `7ft-tol1e-3-relax1-40s` (1e-3; "
    "descent 5.102 against 5.114 m/s; predictor zero: 3.15 at 8 cells). "
    "The HHT tutorials use it.", "",
    "`7ft-tol1e-3-relax1-40s` re-made with the sub-steps (before the "
    "predictor; 49 min on 2 ranks) runs to 40 s; its line stays at "
    "0.2-0.9 m/s throughout, and over 10-40 s it descends at 5.27 m/s "
    "(C_D0 0.94; 5.14 m/s over 20-30 s, 5.24 over 30-40 s) with 4.1 "
    "coupling iterations a step (study tolerance7ftLong above).", ""]


# Why the HHT tutorials start each step's stabiliser from zero: the main
# job from rest with the lagging predictors, restarts from its 3 s state,
# and the structure alone (tests/openfoam/addedMassStabiliser's case)
STABILISER_NOTES = ["## The stabiliser's predictor: a lagging balance "
                    "grows a vibration next to the 7 ft canopy's apex", ""]
STABILISER_NOTES += [
    "With the structure in sub-steps, the 7 ft main job of then (run "
    "`7ft-stiff` now, "
    "12 cells across D0, coupling to 5e-3) with `addedMass.predictor "
    "lastStepMean` stopped at 4.27 s: the coupling did not converge in "
    "20 iterations, its residual alternating between two cloth points "
    "at about 0.77 m from the axis while Aitken's factor fell to 0.05. "
    "The canopy file shows why: the cloth nodes next to the apex (which "
    "slides on the guide wire) vibrated ever faster, 1.2 m/s at 2 s, 3.1 "
    "at 3 s, 8.7 at 3.75 s and 20 m/s at 4.25 s, the rest of the cloth "
    "at 0.1-0.5 m/s; the coupling iterations rose with it, from 2.3 a "
    "step at 1 s to 4.1 at 2 s, 6.5 at 4 s and 9 at 4.25 s. From rest "
    "with `predictor lastStep` the same nodes reach 1.8 m/s at 1 s and "
    "4.4 at 4.5 s, then calm to 0.8 m/s at 6.5 s, while the coupling "
    "takes 4.0, 5.8 and 7.0 iterations a step over the seconds from 1, 3 "
    "and 4 s (stopped at 6.7 s; 12 s would take beyond the main job's 15 "
    "minutes). Restarted from the lastStepMean run's 3 s state (apex "
    "nodes at 3.1 m/s) to 4 s, one change each:", "",
    "| change | apex nodes at 4 s [m/s] | coupling iterations a step |",
    "|---|---|---|",
    "| none (lastStepMean, 5e-3) | 13.5 (stalled at 4.27 s) | 5.2 |",
    "| coupling to 1e-3 | 9.0 | 7.3 |",
    "| predictor lastStep | 7.1 | 5.5 |",
    "| predictor zero | 2.5 (2.2 at 3.25 s) | 2.9 |",
    "| acceleration IQN-ILS | stalled at 4.03 s | 2.8 |", "",
    "Both lagging predictors start a step's balance from the previous "
    "step's acceleration. The balance converges slowly where the air "
    "does not resist the cloth (by m_a/(m + m_a) = 0.94 per iteration "
    "for the 7 ft cloth and its 0.54 kg/m^2), so part of that lag "
    "remains when the interface velocity has converged, and a lagging "
    "restoring force is a negative damping "
    "(src/canopyFoam/coupling/addedMassStabiliser/addedMassStabiliser.H). "
    "The structure alone shows it in the tutorials' scheme "
    "(tests/openfoam/addedMassStabiliser's case with hht, alpha -0.3, "
    "maxOmegaDt 2, the stabiliser of 0.54 kg/m^2 in every direction "
    "balanced at the step's end, 6 iterations a step of 0.01 s, no "
    "air): a node passes the 100 m/s limit after 46 steps with "
    "`lastStep`, 47 with `lastStepMean` and 237 with `zero`. The HHT "
    "tutorials therefore start each step's balance from zero "
    "(`predictor zero`), whose unconverged part acts as extra inertia "
    "instead.", "",
    "What that costs: from rest the main job's steps converge at their "
    "first iteration from 1 s on (1.23 iterations a step over 0-12 s, "
    "mean residual 3.7e-4 over 5-8 s; with the coupling to 1e-3, 1.17 a "
    "step over 3-4 s), so the stabiliser's balance stays zero and its "
    "0.54 kg/m^2 acts as cloth inertia, 15 times the nylon's: the "
    "force m_a a on the cloth's nodes sums to 4-10 % of the load's "
    "(|f| summed over the nodes, canopy.h5 at 2-12 s). A mean "
    "acceleration of zero makes that force zero on average, so the "
    "steady descent is not biased by it; the cloth's own dynamics "
    "(breathing) are. Requiring the balance to converge too (dt times "
    "its change, against the coupling's tolerance) is exact but the "
    "balance then converges by about 0.9 per iteration while the canopy "
    "inflates, and the main job stopped at 0.10 s (20 iterations, "
    "residual 0.005017 against 0.005). A balance that converges in a "
    "few iterations (the stabiliser's mass in the quasi-Newton's "
    "unknowns, or its balance extrapolated per node) is the open "
    "problem.", "",
    "The large canopies in the same sub-steps: the T-10 (100 kg, 11 "
    "cells across D0) from rest with `lastStepMean` took 7.8 coupling "
    "iterations a step, 14.7 over 12-13.7 s, and stalled at 13.78 s (40 "
    "iterations, residual 0.0055). With `zero` it ran 20 s at 1.45 a "
    "step, but the stabiliser's force m_a a summed to 82, 42 and 30 % "
    "of the load at 6, 12 and 18 s (its 2.7 kg/m^2 is 72 times the "
    "cloth's), and the canopy stayed open at 10.16 m (0.95 D0), "
    "descending at 3.84 m/s over 13.3-20 s (C_D0 1.31) where one HHT "
    "step per time step gives 8.94 m and 4.41 m/s; the other large "
    "tutorials moved likewise (T-10 at 163 kg 5.38 against 5.76 m/s, "
    "G-11 5.60 against 5.88, G-11 folded 5.70 against 6.11, C-9 5.31 "
    "against 5.67). So the large canopies keep one HHT step per time "
    "step with `predictor lastStep`, the scheme their records were made "
    "with, and only the 7 ft tutorial takes sub-steps.", "",
    "**The predictor is not the whole cause.** At 18 cells across D0 "
    "(`7ft-cpd18-tol1e-3-relax1-40s`, coupling to 1e-3), where "
    "`lastStepMean` ran from rest to 26.7 s with its cloth at 0.1-0.3 "
    "m/s over 0-15 s, `zero` grows the same vibration next to the apex "
    "(0.7 m/s at 1.5 s, 2.5 at 1.75 s, 10 at 2 s; the coupling "
    "iterations rise from 2.3 a step at 1-1.5 s to 9 at 2 s) and the run "
    "stopped at 2.11 s (40 iterations, residual 0.088). Restarted from "
    "its 1.5 s state with `lastStepMean`, or with the apex off the guide "
    "wire, it stops at 2.01 and 2.11 s. The predictor changes when and "
    "where the apex's cloth starts to vibrate, not whether; what drives "
    "it (the cloth next to the apex, the stabiliser's balance in "
    "sub-steps, the forcing there) is open. The record of that run in "
    "the table above is the `lastStepMean` run.", "",
    "What moved: the main job of then (`7ft-stiff` now) descends at "
    "5.62 ± 0.09 m/s (95 %) over 5-8 s, C_D0 0.826, projected diameter "
    "1.90 m, in 2.1 minutes on 2 ranks at 1.23 coupling iterations a "
    "step; before the sub-steps (one HHT step a time step, predictor "
    "lastStep) it gave 5.50 m/s, C_D0 0.86, in 12.2 minutes at 4.1. The "
    "8-cell case of tests/foamRun/flatCircular7ft descends at 3.252 m/s "
    "at 2 s (3.300 with lastStepMean).", ""]

# Why the 7 ft tutorial's stabiliser balances the triangles' mean
# acceleration: the one-node model, the structure alone, and the 18-cell
# runs that stopped without it
# The coupling's residual over its whole iterate: what it found and what
# moved (written by hand; the numbers are the runs' records)
RESIDUAL_NOTES = ["## The coupling's residual over its whole iterate", ""]
RESIDUAL_NOTES += [
    "The strong coupling iterates on the interface's normal velocity and "
    "carries secondary data with it: the whole velocity the no-slip "
    "forcing imposes and the added-mass stabiliser's balance "
    "(interfaceIterate.H). Its residual was the change of the normal "
    "velocity alone. A step's first iteration compares the structure's "
    "answer with the previous step's velocity, so every step whose "
    "normal velocity changed by less than the tolerance (5e-3 of Uref = "
    "4 m/s, i.e. 0.02 m/s rms, an acceleration of 4 m/s² at the 7 ft "
    "canopy's 5 ms steps) ended after one iteration, whatever the "
    "tangential velocity and the balance did. With predictor zero (the "
    "7 ft and cross tutorials) the balance of such a step was zero: the "
    "stabiliser's 0.54 kg/m², 15 times the nylon's, acted as cloth "
    "inertia in every motion slower than that, the breathing among them. "
    "7ft-mapped-cpd27-co0.25 took 80 % of its steps in one iteration "
    "(first-iteration residual: median 0.0017). The T-10's couplingT10 "
    "runs with predictor zero (1.00 iteration a step) were the same "
    "effect, not a converged balance.", "",
    "The residual now covers the whole iterate: the change of the whole "
    "velocity with forcing tangential noSlip (the normal velocity's "
    "otherwise), and with the stabiliser the balance's change, as the "
    "velocity change it makes over the step, dt m_a/(m + m_a) times the "
    "change of abar, per triangle as the interface velocity (a node-scale "
    "motion with a zero mean over every triangle, which the forcing does "
    "not see, does not count). tests/openfoam/couplingResidual slides a "
    "free disc of the 7 ft nylon in its own plane in still air: with the "
    "old residual every step ended in one iteration, the disc without "
    "a stabiliser slid 2.731 mm in 0.05 s on an explicit tangential "
    "coupling and the stabilised one 1.664 mm (39 % short); with the "
    "residual over the whole iterate both take 4-16 iterations a step "
    "and slide 2.594 and 2.603 mm (0.3 % apart).", "",
    "The T-10 tutorial's stabiliser (lumped, from the last step's "
    "acceleration) does not converge under the new residual: from the "
    "inflated state (T10-mapped-cpd13) its balance residual fell by "
    "about 0.96 an iteration and the first step stopped after 40 "
    "iterations at 0.0078 against 0.005. The tutorial now balances as the "
    "7 ft does (filter triangleMean, predictor zero). The C-9's and "
    "1/3-scale G-11's tutorials keep the lumped balance from the last "
    "step; their runs in this report were made with the old residual.",
    "", "What moved (each run against its record before the change):", "",
    "| run | coupling it./step (max) | wall time | descent [m/s] | C_D0 | Dp/D0 | breathing |",
    "|---|---|---|---|---|---|---|",
    "| 7ft-default, before | 1.32 (7) | 7.8 min | 6.17 ± 0.03 | 0.685 | 0.781 | 2.44 Hz, 3.7 mm (band) |",
    "| 7ft-default, after | 3.04 (16) | 15.4 min | 5.70 ± 0.38 | 0.802 | 0.786 | 1.41 Hz, 12 mm (band) |",
    "| T10-mapped-cpd13, before | 2.96 (7) | 1.7 min | 6.072 ± 0.026 | 0.832 | 0.763 | 0.23 Hz, 3.2 cm |",
    "| T10-mapped-cpd13, after | 1.49 (7) | 0.9 min | 6.071 ± 0.017 | 0.832 | 0.765 | 0.18 Hz, 3.3 cm |",
    "| T10-mapped-cpd20, before | 3.54 (10) | 7.0 min | 6.474 ± 0.036 | 0.732 | 0.748 | 0.42 Hz, 11.1 cm |",
    "| T10-mapped-cpd20, after | 1.50 (10) | 2.7 min | 6.426 ± 0.039 | 0.743 | 0.751 | 0.21 Hz, 2.4 cm |",
    "",
    "The T-10 descends as before within the intervals (C_D0 +0.0 % and "
    "+1.5 %) at half the iterations or fewer and under half the wall "
    "time: the lagging balance of the last step's acceleration was what "
    "took its iterations (study couplingT10), and the balance from zero "
    "converges in 1.5 a step at 13 and 20 cells. Its breathing is slower "
    "and at 20 cells smaller (0.21 Hz, 2.4 cm against 0.42 Hz, 11.1 cm); "
    "neither level holds more than about two periods in its 10 s, so "
    "neither value is converged. The 7 ft canopy's main job needs 3.0 "
    "iterations a step instead of 1.3 and twice the time (15.4 min on 2 "
    "ranks, above the main job's 15). Its descent no longer levels: it "
    "rises to 6.6 m/s at 5.5 s, falls to 5.3 m/s at 8.5 s and is back at "
    "6.2 m/s at 12 s, so the 8-12 s window holds a rising half-swing "
    "(drift +1.09 m/s) and C_D0 0.802 over it is not a steady value. "
    "Before, the steps whose velocity changed by less than 0.02 m/s had "
    "the stabiliser's 0.54 kg/m^2 as cloth inertia (section \"The "
    "stabiliser's filter\"); whether this slow swing of the descent is "
    "the canopy's and its wake's own dynamics, now that the cloth has "
    "its own inertia, or a defect of the converged balance, the 12 s run "
    "cannot tell from its 12 s. Run on to 40 s (7ft-default-40s as it "
    "was then, at commit 1d95cf6; its record now is of the current "
    "tutorial, below) it levels at "
    "6.29-6.59 m/s from 12 s (6.34 ± 0.17 m/s over 10-22.15 s, C_D0 "
    "0.648, 2.94 iterations a step), then stops at 22.15 s: the structure "
    "step of a second coupling iteration diverged, a cloth node passing "
    "100 m/s. The nodes that ran away (161-164, 168, 208) lie 0.94-0.96 m "
    "from the flat cloth's centre, within one fabric edge (0.148 m) of "
    "the skirt (1.067 m); in the inflated canopy the skirt gathers "
    "inward, and there the cloth, without stiffness in compression, had "
    "collapsed: at 21.5 s the smallest triangle had 0.3 % of its flat "
    "area and the most compressed edge 3 % of its length. The earlier "
    "code ran the same case to 40 s (6.22 ± 0.04 m/s, C_D0 0.674 over "
    "10-40 s).", "",
    "Restarted from the run's 21.5 s state it stops again at 22.1567 s "
    "(the same node and speed: restarts are exact), and each variant "
    "below was restarted from that state and run to 23 s (1.5 s, about "
    "270 steps):", "",
    "| variant from 21.5 s | outcome | coupling it./step |",
    "|---|---|---|",
    "| as run (balance endOfStep, sub-steps Λdt ≤ 2) | stops at 22.157 s (node 164) | 2.38 |",
    "| stabiliser mass 0.27 kg/m² instead of 0.54 | stops at 21.667 s (node 168) | - |",
    "| coupling tolerance 2.5e-3 instead of 5e-3 | stops at 21.638 s (node 208) | - |",
    "| distribution consistent (the triangles' added mass) | coupling not converged at 21.677 s | - |",
    "| sub-steps Λdt ≤ 1 | runs to 23 s | 3.27 |",
    "| balance stepMean (the step's mean acceleration) | runs to 23 s | 1.04 |",
    "| balance stepMean, sub-steps Λdt ≤ 1 | runs to 23 s | 2.48 |",
    "| the acceleration iterating on the balance too (below) | stops at 22.140 s (node 50) | 1.93 |",
    "", "A smaller or better converged balance does not save the run, so "
    "the stop is not the stabiliser's partly converged balance (the "
    "one-node model's growth, suggested before): the collapsed cloth at "
    "the skirt is near a runaway that any perturbation of the step can "
    "start. Two variants carried it past 22.16 s, and neither holds from "
    "rest. With sub-steps of Λdt ≤ 1 the main job stopped at 0.51 s: "
    "the balance residual went round a cycle of five iterations (0.022 "
    "falling to 0.0065, then back), rising whenever Aitken's factor "
    "returned to 1, which the normal velocity's residual (0.0006-0.002) "
    "alone then set. Balanced by the step's mean acceleration (its mass "
    "terms over the sub-steps then cancel the balance's impulse exactly "
    "at convergence), the main job inflates faster (4.47 m/s at 1 s "
    "against 4.02) and then stops at 3.39 s: from 2.25 s its cloth's "
    "nodes moved up to 3 m/s against the canopy's median (a tenth of "
    "them faster than 1.4-1.8 m/s; on endOfStep at most 0.5-1.0 m/s, a "
    "tenth faster than 0.25-0.35 m/s), and a node 0.85 m from the "
    "centre ran away. Both experiments are in "
    "the repository's history (the tutorial's settings in commits "
    "954c013 and 1fc4445, reverted). What sets the skirt's gathering (the "
    "hem shortens by 30 % on average, its radius 0.75 m in the main job "
    "against the flat 1.067 m, and a cloth without compression stiffness "
    "takes that shortening where it first buckles instead of spreading "
    "it) is the open question of the inflated shape: the remedy is a "
    "physical model of the gathered "
    "cloth, not the coupling.", "",
    "### The acceleration iterates on the balance too", "",
    "The cycle above showed a gap: the coupling's acceleration made its "
    "next iterate from the normal velocity alone, with the balance and "
    "the tangential velocity carried as secondary data, so Aitken's "
    "factor followed a residual that had converged while the balance "
    "had not, and IQN-ILS's least-squares Jacobian had no column for the "
    "balance at all. The acceleration now iterates on what the residual "
    "measures (interfaceIterate.H): the velocity the forcing imposes (the "
    "whole velocity with tangential noSlip) and the balance as the "
    "velocity change it makes per triangle over the step "
    "(addedMassStabiliser::balanceVelocities), the nodal balance, the "
    "normal velocity and the markers moving with it. What moved, on the "
    "7 ft main job's set-up:", "",
    "| case | before | after |",
    "|---|---|---|",
    "| from rest, Aitken (the tutorial), the first 184 steps (0-1.5 s) | 5.79 it./step (max 16) | 5.22 (max 15); descent at 1 and 1.5 s 4.015 and 4.945 m/s against 4.023 and 4.943 |",
    "| restart from 21.5 s to 22.14 s, Aitken | 2.38 it./step | 1.93 |",
    "| from rest, IQN-ILS (initial 1, reuse 8, filter 1e-3), 0-1 s | stops at 0.061 s (balance residual 0.017 after 20 iterations) | 4.16 it./step (max 18; 2.6 over the last 30 steps) against Aitken's 7.0 before |",
    "| restart from 21.5 s to 22.1 s, IQN-ILS | - | 1.95 it./step (max 4) |",
    "| tests/openfoam/couplingResidual, reference / stabilised | 5-10 / 4-16 it./step, slides 2.5944 / 2.6026 mm | 7 / 4-6, slides 2.5927 / 2.6129 mm (0.78 % apart; limit 2 %) |",
    "",
    "The main job from rest to 12 s on this acceleration: with Aitken's "
    "relaxation (the tutorial's until then; commit 109d77a) it stopped "
    "at 9.698 s, when node 161 passed 100 m/s in a structure sub-step of "
    "a step's first iteration. Node 161 is a suspension line's "
    "attachment on the hem; the cloth around it was gathering (one of "
    "its two triangles at 11 % of its flat area at 9.5 s, an edge "
    "compressed by 31 %), and in the failing step its line stretched by "
    "2 % (about 38 N, ten times its share of the payload's weight) and "
    "flung it. With IQN-ILS (7ft-default-iqn, the tutorial's now) the "
    "same case runs to 12 s in 10.7 minutes on 2 ranks at 2.07 "
    "iterations a step (at most 18; 1.89 over 8-12 s): 5.77 ± 0.19 m/s "
    "(95 %; drift +0.53 m/s, not steady), C_D0 0.782, Dp/D0 0.813, "
    "against 5.70 ± 0.38 m/s, C_D0 0.802 and 3.04 iterations a step "
    "(15.4 minutes) on the previous acceleration. Restarted from the "
    "Aitken run's 9.5 s state and run to 10.5 s, the stop repeats "
    "exactly as it ran; with the cloth's compression ratio 0.001 or "
    "0.01 (fabric.compressionRatio; the physical value is below 1e-4, "
    "section \"The cloth's stiffness in compression\") or the structure "
    "in sub-steps of Λdt ≤ 1 it runs through 10.5 s. Like the 40 s "
    "run's stop at 22.15 s, this is the gathered skirt on the edge of a "
    "runaway that a small change of the step's path starts or avoids; "
    "IQN-ILS passing it is no proof that it will not meet another: run "
    "on to 40 s (7ft-default-40s) the tutorial on IQN-ILS stops at "
    "12.365 s, 0.37 s after the main job ends, when node 134 (0.87 m "
    "from the flat cloth's centre, next to the hem) passes 100 m/s in a "
    "structure sub-step of a step's second iteration. Restarted from "
    "its 12.25 s state the stop repeats exactly; with the cloth's "
    "compression ratio 0.001 or the structure in sub-steps of Λdt ≤ 1 "
    "it runs through 13.25 s. From rest, sub-steps of Λdt ≤ 1 on IQN-ILS "
    "stop the main job at 0.33 s, as on Aitken's relaxation at 0.51 s: "
    "the balance, the last of twice as many sub-steps' end acceleration, "
    "does not converge in 20 iterations while the canopy inflates "
    "(balance residual 0.0102, velocity 0.0012).", "",
]


CELL_REACTION_NOTES = ["## The load is the reaction of the force in the "
                       "cells", ""]
CELL_REACTION_NOTES += [
    "**What flung the gathered skirt.** The multi-direct forcing "
    "accumulates each marker's force from step to step (F_m += (u_target "
    "- u_m) A_m h_m / dt, ibForcing.H), and the full-load scheme (load "
    "ibForce) took each marker's force as the load on its cloth. A "
    "pattern of forces that alternates between neighbouring markers, or "
    "opposes itself on two layers of cloth folded within one kernel "
    "width, spreads to almost nothing in the cells: the air does not "
    "feel it, so no velocity error stops it from growing. The cloth felt "
    "it marker by marker. In 7ft-default-40s's state at 12.25 s (the "
    "tutorial on IQN-ILS, reaction markers) the 860 markers carry 54.4 N "
    "in all, 0.063 N each on average, but the median marker's force is "
    "1.49 N and the largest 6.66 N, with signs alternating between "
    "neighbours; a skirt triangle folded to 3 % of its flat area carried "
    "2.1 N (a pressure jump of 7010 Pa against the canopy's mean 38 Pa). "
    "Restarted from that state with the cloth's compression ratio 1e-4 "
    "(the physical bound, section \"The cloth's stiffness in "
    "compression\") it stopped at 12.3605 s, when hem node 169 passed "
    "100 m/s; the load written with the stop gave one hem triangle 11 "
    "kN.", "",
    "**The load as the reaction of the force in the cells** "
    "(coupling.load.reaction cells, ibForce.H). The force the markers "
    "had accumulated by the step's start is taken where the air feels "
    "it, in the cells (f_i V_i = sum_n w_in F_n), and shared back among "
    "the markers in proportion to A_m h_m |w_im| "
    "(ibStencil::shareSpread); the step's own increment stays each "
    "marker's, so that within a step the coupling iterates on the local "
    "response the stabiliser models. The total is the IB force's "
    "exactly (the load on the cloth stays minus the force on the air), a "
    "load proportional to the markers' volumes comes back as it was "
    "where the weights are non-negative, and a pattern that spreads to "
    "nothing comes back as nothing (tests/openfoam/ibInterpolation, to "
    "1e-15 of the forces). The air's forcing is unchanged, and the "
    "markers' forces still accumulate such patterns (in the main job the "
    "median marker's force is 3.79 N at 12 s and 4.88 N at 16 s, against "
    "0.066 N of load per marker); the air does not feel them and the "
    "cloth no longer does. Two other forms failed from rest: sharing the "
    "step's increment too stopped the main job at 0.30 s (the balance "
    "residual stayed at 0.0074 after 20 iterations while the canopy "
    "inflated: the coupling then iterates on a response spread over "
    "neighbours that the stabiliser's lumped mass does not model), and "
    "re-sharing the markers' forces themselves at each step's start (so "
    "that the patterns cannot grow) stopped it at 0.071 s (balance "
    "residual 0.0134): that changes the air's forcing too, and every "
    "step then has to rebuild the fine part of the force that holds the "
    "air at the markers.", "",
    "| restarted from | to | reaction markers (as run) | compression ratio 1e-4 | 0.001 | Λdt ≤ 1 | reaction cells |",
    "|---|---|---|---|---|---|---|",
    "| 7ft-default-40s at 12.25 s (IQN-ILS) | 13.25 s | stops 12.365 s | stops 12.3605 s | 2.00 it./step | 1.84 | 2.05 |",
    "| the main job on Aitken's relaxation at 9.5 s | 10.5 s | stops 9.699 s | 2.68 | 2.28 | 2.47 | 3.69 |",
    "",
    "**What moved** (the 7 ft tutorial on reaction cells, the cloth "
    "still without stiffness in compression). The main job (7ft-default, "
    "from rest to 12 s) runs in 11.1 minutes on 2 ranks, report "
    "included, at 2.22 iterations a step (at most 18): over 8-12 s 5.17 ± "
    "0.33 m/s (drift +0.90 m/s: the descent still rises), C_D0 0.976, "
    "Dp/D0 0.793, where each marker's own force gave 5.77 ± 0.19 m/s, "
    "C_D0 0.782 and Dp/D0 0.813 in 11.3 minutes (2.07 iterations a "
    "step). Its course is the same shape (peak at 6 s, a dip at 8 s, "
    "rising again) about 0.5 m/s slower throughout. Run on to 40 s "
    "(7ft-default-40s, continued from the main job's 12 s state) it "
    "reaches 40 s, past both earlier stops (12.37 s on IQN-ILS, 22.15 s "
    "on the earlier acceleration): over 10-40 s 5.46 ± 0.03 m/s (drift "
    "+0.05), C_D0 0.874, Dp/D0 0.790, the crown 0.245 D0 above the "
    "skirt, the diameter breathing at 1.32 Hz (St = f Dp/V = 0.41) with "
    "8 mm amplitude, 2.07 iterations a step (2.00 in the window, at most "
    "18). With each marker's own force the same set-up had given 6.22 ± "
    "0.04 m/s and C_D0 0.674 over 10-40 s (before the coupling's residual "
    "covered the balance). The drag rose by 30 % at the same projected "
    "diameter, with the crown standing higher (0.524 m above the skirt "
    "against 0.471-0.492 m in the earlier runs) and the skirt's outer "
    "ring folding less (mean fold angle between neighbouring triangles "
    "32° against 33-45°). Across the 7 ft runs to 40 s (read over 10-40 "
    "s; all but the first on each marker's own force, on earlier "
    "codes) the drag follows the skirt's mean radius and the crown's "
    "height, not the largest radius that Dp measures:", "",
    "| run (10-40 s) | C_D0 | Dp/D0 | crown above skirt [m] | skirt radius, mean [m] | cloth folded beyond 90° |",
    "|---|---|---|---|---|---|",
    "| 7ft-default-40s (load from the cells) | 0.874 | 0.790 | 0.524 | 0.793 | 1.2 % |",
    "| 7ft-default-edge0.83-40s (0.099 m cloth) | 0.792 | 0.809 | 0.510 | 0.797 | 2.2 % |",
    "| 7ft-default-loss0.1-40s | 0.719 | 0.807 | 0.476 | 0.776 | 3.2 % |",
    "| 7ft-default-bend1000-40s | 0.684 | 0.797 | 0.486 | 0.737 | 1.4 % |",
    "| 7ft-default-LES-40s | 0.674 | 0.780 | 0.497 | 0.722 | 3.0 % |",
    "| 7ft-default-w11-40s (box 11 D0) | 0.658 | 0.792 | 0.467 | 0.740 | 3.9 % |",
    "", "The load from the cells holds the skirt more open and the crown "
    "higher: a deeper cup at the same largest diameter, and the finer "
    "cloth on each marker's own force went the same way. So the extra "
    "drag is carried by the shape, which the alternating patterns had "
    "crumpled at the skirt; how the wake follows it is not analysed. "
    "Knacke's flat circular canopies give C_D0 "
    "0.75-0.80 (section \"The cloth's stiffness in compression\"), so the "
    "new value is 9-16 % above the handbook's where the old one was 10-16 "
    "% below; neither is a converged value (below).", "",
    "Without the hinge dashpots (7ft-default-bend0: bendingDamping 0, "
    "the load from the cells) the main job stops at 0.22 s: its coupling "
    "does not converge in 20 iterations (balance residual 0.0107, slip "
    "0.22 of Uref) while the canopy starts to inflate. So the dashpots "
    "are still needed with the new load; what keeps the balance from "
    "converging without them is not yet analysed (study "
    "hingeDampingCells7ft).", "",
    "**The T-10** (study cellReactionT10: 163 kg on the guide wire, the "
    "extended skirt continuing T10-skirt-cpd13-cloth0.446-80s, to 12 s, "
    "read over 2-12 s; each marker's own force re-run on the current "
    "coupling beside it):", "",
    "| cells across D0 | load | descent [m/s] | C_D0 | Dp [m] | it./step |",
    "|---|---|---|---|---|---|",
    "| 13 | each marker's own | 6.071 ± 0.017 | 0.832 | 8.18 | 1.47 |",
    "| 13 | from the cells | 6.142 ± 0.126 (drift -0.35) | 0.813 | 8.35 | 1.37 |",
    "| 20 | each marker's own | 6.425 ± 0.039 | 0.743 | 8.04 | 1.47 |",
    "| 20 | from the cells | 6.404 ± 0.043 | 0.748 | 8.26 | 1.41 |",
    "",
    "On the T-10 the load from the cells moves C_D0 by -2.3 % and +0.7 % "
    "(inside the resolution study's GCI of 34.7 %) and opens the canopy "
    "by 2-3 % in projected diameter, with a few per cent fewer coupling "
    "iterations; its tutorial, like the C-9's and the G-11's, still takes "
    "each marker's own force.", "",
    "Every 7 ft study in this report but the main job's two runs and "
    "hingeDampingCells7ft was made with each marker's own force (their "
    "runs keep coupling.load.reaction markers). The studies over 10-40 s "
    "(domain7ftLong, damping7ftLong, turbulence7ftConverged, "
    "edgeLength7ftLong) compare with 7ft-default-markers-40s, the main "
    "job's 40 s run on each marker's own force; those over 8-12 s that "
    "compare with 7ft-default-12s (hingeDamping7ft, materialDamping7ft, "
    "tapes7ft and others) compare two loads, as each study's section "
    "says where its runs' definitions differ; the resolution, time-step "
    "and cloth studies are to be re-made on the cells' load before their "
    "converged values stand for the tutorial.", "",
]


WRINKLING_NOTES = ["## The cloth's stiffness in compression", ""]
WRINKLING_NOTES += [
    "**What real cloth does.** The seed's Model-II springs resist "
    "shortening as stiffly as stretching. Canopy cloth does not: it "
    "buckles into wrinkles under an almost vanishing compressive load "
    "(\"the fabric is able to resist tensile stresses but buckles "
    "(wrinkles) almost immediately under compressive loads\", Flores, "
    "Ortega & Oñate, CIMNE report on the PUMI_MEM parachute solver, "
    "scipedia.com/public/Flores_et_al_2011a; membranes \"fail to carry "
    "any noteworthy compressive stresses due to the formation of "
    "wrinkles\", Pagitz & Abdalla, Comput. Mech. 46 (2010) 747). For "
    "this cloth, MIL-C-7020 Type I, 0.003 in (76 µm) thick with E t = "
    "2919 N/m, a plate's bending stiffness E t^3/12 is at most 1.4e-6 N m, "
    "so a strip one fabric edge long (0.18 m) buckles at π² B/L² ≈ 4e-4 "
    "N/m and a 1 cm wrinkle at 0.14 N/m, against a meridional tension of "
    "about 15 N/m (Δp R/2 at 27 Pa). The physical compression ratio "
    "(`fabric.compressionRatio`, the springs' stiffness while shorter "
    "than their rest length over their tensile stiffness) is therefore 0 "
    "to within 1e-4: a slack spring stands for the cloth wrinkled between "
    "its nodes (tension-field theory).", "",
    "**What the cloth without compression should look like.** A flat "
    "circle cannot close into a cup without gathering: cloth at "
    "arclength s from the apex had a hoop length 2πs and sits at a "
    "radius r(s) < s, so the whole inflated canopy is slack in hoop. "
    "With no hoop stress and a uniform pressure jump the meridian obeys "
    "r T = C and dφ/ds = (Δp/C) r (python/canopyfoam/tension_field_shape.py, "
    "the Aeronautical Research Council's approximate theory of gore "
    "shape, reports.aerade.cranfield.ac.uk/handle/1826.2/3410; with the "
    "rim free it is Paulsen's Mylar balloon, which the tests reproduce to "
    "1e-10). With the lines (1 D0) continuing the skirt's tangent: Dp/D0 "
    "= 0.676 (0.664 for lines of 0.85 D0, 0.700 for 1.5 D0), the skirt at "
    "0.657 D0, the crown 0.258 D0 above it, the smooth surface 87 % of "
    "the cloth's. The handbook's Dp/D0 = 0.67-0.70 for flat circular "
    "canopies (Knacke, Table 5-1) is this shape. The model leaves out "
    "the pressure's fall from crown to skirt and the gores' bulge "
    "between the lines.", "",
    "**What the runs show** (table above; 12 cells across D0 unless "
    "said). The cloth keeps the stiff cloth's shape down to 1 % of its "
    "stiffness in compression (Dp/D0 0.891 / 0.888 / 0.882 at 1 / 0.1 / "
    "0.01, silhouette 0.838 / 0.834 / 0.828 D0): 1 % still carries ~3 "
    "N/m at 10 % hoop shortening, a fifth of the meridional tension. "
    "Without compressive stiffness the canopy closes: Dp/D0 "
    "0.83 and silhouette 0.77 D0 at 12 cells, 0.78 and 0.73 at 18, and "
    "its crown follows the tension-field meridian to 0.01-0.02 R0 in "
    "radius out to s = 0.73 R0 at 18 cells (`python3 -m "
    "canopyfoam.tension_field_shape build/validation/"
    "7ft-cpd18-compression0 5 12`: r/R0 0.373 / 0.488 / 0.580 / 0.647 "
    "against 0.371 / 0.485 / 0.568 / 0.643 at s = 0.38 / 0.50 / 0.60 / "
    "0.73). The skirt stays wider than the model (0.716 R0 against "
    "0.657 at 18 cells, 0.79 at 12): the hem, two fabric edges between "
    "neighbouring lines at 12 cells, bulges out between them taut; it "
    "comes in as the cloth is refined (three edges a gore at 18 "
    "cells). The crown stands 0.20-0.22 D0 above the skirt without "
    "compressive stiffness (0.26 in the model); the stiff cloth's crown "
    "is flatter, 0.17 D0, and its skirt out at 0.84 D0. Over 10-40 s (7ft-compression0-40s) the canopy without "
    "compressive stiffness descends at 5.26 ± 0.10 m/s (C_D0 0.94, "
    "drift +0.3 m/s over the interval, silhouette 0.79 D0), steadier "
    "than the stiff cloth (7ft-tol1e-3-relax1-40s: 5.09 ± 0.24, drift "
    "-0.73 m/s, still slowing, silhouette 0.86 D0). Over 5-12 s the "
    "18-cell canopy descends at 6.22 ± 0.14 m/s (C_D0 0.67): read over "
    "the same transient interval as the 12-cell run, which falls from 6.0 "
    "to 4.8 m/s within it (5.50 ± 0.60), the two are not comparable; "
    "the resolution of the descent needs the long window.", "",
    "**At 27 cells** (7ft-cpd27-compression0: 537 000 cells, 61 minutes "
    "on 2 ranks to 12 s, 1.19 coupling iterations a step) the canopy "
    "repeats the 18-cell one over 5-12 s: 6.24 ± 0.12 against 6.22 ± "
    "0.14 m/s, C_D0 0.669 against 0.674, Dp/D0 0.778 against 0.782, "
    "silhouette 0.724 against 0.729 D0, skirt radius 0.717 against 0.716 "
    "R0. The crown follows the tension-field meridian to 0.01-0.03 R0 "
    "(r/R0 0.386 / 0.488 / 0.582 / 0.675 against the model's 0.373 / "
    "0.470 / 0.564 / 0.648 at s = 0.38 / 0.48 / 0.60 / 0.75 R0), and the "
    "skirt stays at 0.717 R0 against the model's 0.657. The shape has "
    "converged in the resolution (18 to 27 cells, both structure and "
    "fluid) and the skirt's 0.06 R0 is the model's to explain: it takes "
    "the pressure jump uniform, where on a real canopy it falls towards "
    "the skirt, and a meridian loaded less near the skirt turns in less "
    "(dφ/ds = Δp r / C). The 12-cell level is the outlier: its "
    "hem, two fabric edges a gore, stays out at 0.79 R0, and its descent "
    "falls through the interval.", "",
    "**The tutorial's default** is this cloth since these runs "
    "(`fabric.compressionRatio 0` in tutorials/parachutes/flatCircular7ft; "
    "the runs made before say `fabric/compressionRatio 1` among their "
    "edits, `SEVEN_STIFF` in python/canopyfoam/validation_runs.py), on 18 "
    "cells across D0 (section \"The main job's resolution\").", "",
    "With fabric finer than the cells (7ft-edge0.83-compression0, edge "
    "0.83 finest cells) the cloth without compressive stiffness stopped "
    "at 8.09 s: cloth nodes moved at 0.3-1.5 m/s relative to the payload "
    "from 6.75 s, and one passed the 100 m/s limit within a step. The "
    "IB kernel spreads each marker's force over three cells, so a "
    "triangle smaller than a cell feels no resistance from the air to "
    "node-scale motion; without compressive stiffness such a motion "
    "meets neither air nor cloth. The tutorials keep the fabric's edge "
    "at 1.25 finest cells.", "",
]


# The main job as it is (study default7ft)
MAIN_JOB_PROSE = [
    "The main job, the tutorial as it is (run 7ft-cpd12-damped-70s): "
    "on the drop test's "
    "guide wire (`guideWire` in constant/canopyProperties: the payload "
    "and the canopy's apex slide on a vertical wire), the cloth without "
    "stiffness in compression (`fabric.compressionRatio 0`: section "
    "\"The cloth's stiffness in compression\"), the load taken from the "
    "cells (section \"The load is the reaction of the force in the "
    "cells\"), the hinge dashpots during the first inflation only "
    "(`fabric.bendingDampingUntil 2`: study resolution7ftUntil2), the "
    "markers half a cell apart (`forcing.markerSpacingCells 0.5`: study "
    "markers7ftTutorial), nylon's material damping in the cloth and the "
    "lines (Kelvin-Voigt dashpots of loss factor 0.02 at 2 Hz: "
    "`fabric.damping 4.02`, `lines.damping 15.8`; studies iterations7ft "
    "and damping7ftTutorial), 12 cells across D0 at the canopy, from rest "
    "to 70 s, read over 30-70 s (the damped canopy still slows over "
    "10-30 s: study levels7ftDamped), written every 0.5 s. 7ft-cpd12-markerhalf-40s is the "
    "tutorial before nylon's damping: the cloth's and lines' dashpots at "
    "a loss factor of ~5e-5, from rest to 40 s, read over 10-40 s (study "
    "window7ft12: a 10-15 s mean sits on the slow swing after the "
    "overshoot), written every 0.25 s, which every earlier 7 ft run that "
    "does not set them restores (`SEVEN_UNDAMPED` in "
    "python/canopyfoam/validation_runs.py). 7ft-cpd12-until2-40s is the "
    "tutorial with its markers a cell apart, the library's default, as it "
    "was until the markers' study; 7ft-default is the tutorial before the "
    "long window: the dashpots "
    "throughout, 18 cells across D0, to 15 s, read over 10-15 s; "
    "7ft-default-follower is that with the pressure load following the "
    "cloth within the structure's sub-steps (section \"The pressure load "
    "within a step\"). 7ft-stiff is the default before both: the seed's "
    "cloth as stiff in compression as in tension on 12 cells, to 12 s, "
    "read over 5-8 s like the runs of the studies made with it. 7ft-free "
    "is the same case in free flight (the tutorial's default until the "
    "guide wire), read over 4-7 s before its swing: from about 6.5 s the "
    "parachute swings, and over 8-12 s it descends at 4.60 ± 0.94 m/s "
    "with the suspension up to 47°.", ""]

# What the 12-cell level read over 10-15 s and over 10-40 s shows (study
# window7ft12)
WINDOW_12_PROSE = [
    "From rest every level of the 7 ft tutorial overshoots to about 6.1 "
    "m/s at 5-7 s and then swings slowly about its mean, with periods of "
    "5-10 s: the 12-cell level with the dashpots off from 2 s falls to "
    "5.17-5.28 m/s at 11-13 s and holds at 5.4-5.7 from 15 s to 40 s. "
    "Its 10-15 s mean is therefore a phase of that swing: C_D0 0.917 "
    "over 10-15 s against 0.865 over 10-40 s (5.33 ± 0.14 against 5.49 "
    "± 0.07 m/s), a window error of +6 %; with the dashpots throughout "
    "0.822 against 0.844 (-3 %). Over 10-40 s the level without the "
    "dashpots after 2 s is within 0.6 % of the converged value (0.870 ± "
    "1.6 %, study resolution7ftUndampedContinued) and the one with them "
    "3.0 % below it; the first breathes at 1.23 Hz (St 0.38), its "
    "projected diameter's peak 15.8 cm, the second shows 1.2 cm. The "
    "40 s run took 7.8 minutes on 2 ranks (2.47 coupling iterations a "
    "step), the damped one 5.3 minutes (1.26). So the main job reads "
    "10-40 s of a 40 s run on 12 cells across D0 (the cheapest setting "
    "within 5 % of the converged C_D0: section \"The main job's "
    "resolution\"), where the 18-cell level to 15 s took 13.8 minutes "
    "and its 10-15 s window carries the same swing.", ""]

# What the tutorial's 12- and 18-cell levels show over 10-40 s (study
# resolution7ftUntil2Long)
UNTIL_TWO_LONG_PROSE = [
    "Over 10-40 s the tutorial with its markers a cell apart gives C_D0 "
    "0.865 on 12 cells "
    "(5.49 ± 0.07 m/s) and 0.893 on 18 (5.40 ± 0.07 m/s; Dp/D0 0.800 and "
    "0.809, breathing at 1.23 and 1.27 Hz, St 0.38 and 0.41, with 15.8 "
    "and 11.1 cm): 3.3 % apart, inside the pair's combined 95 % interval "
    "of ±3.5 % in C_D0 (each ±2.5 %, twice the descent's relative "
    "half-width). The two-level GCI above (Fs 3 over a ratio of 1.5) turns "
    "that unresolved difference into 19 %: it bounds the window's "
    "statistics as much as the mesh. Against the converged 0.870 ± 1.6 % "
    "(study resolution7ftUndampedContinued) the 12-cell level is 0.6 % "
    "below and the 18-cell level 2.7 % above. The 18-cell run continued "
    "7ft-cpd18-until2-15s from 15 s (41.7 minutes on 2 ranks in all, "
    "2.63 coupling iterations a step). The 27-cell level over 10-40 s "
    "(7ft-cpd27-until2-40s) continues 7ft-cpd27-until2-15s from 15 s and "
    "stands at 16.75 s (about 5-6.5 minutes of wall time a simulated "
    "second on 2 ranks): with the markers now half a cell apart, study "
    "resolution7ftMarkerHalf is the tutorial's resolution, and this "
    "level is made only if that study asks for the comparison. On 8 "
    "cells across D0 the tutorial's canopy does not hold (study "
    "coarse7ftTutorial).", ""]

# What the tutorial shows on 8 cells across D0 (study coarse7ftTutorial)
COARSE_TUTORIAL_PROSE = [
    "On 8 cells across D0 (0.267 m cells, the fabric's edge 0.33 m) the "
    "tutorial does not hold a steady canopy. With its own time step the "
    "coupling did not converge at 17.73 s (20 iterations, residual 0.079, "
    "slip 0.23; the last good state, 17.72 s, written); over 10-17.7 s "
    "it descended at 5.23 ± 0.10 m/s (C_D0 0.95). With half the step it "
    "ran to 40 s, but its projected diameter shrinks from 1.69 m (0.79 "
    "D0) over 10-12 s to 1.33 m over 28-30 s, and from about 30 s the "
    "canopy closes (0.23 m at 38-40 s) and the descent speeds up to 12 "
    "m/s at 40 s. 8 cells across D0 is therefore below the tutorial's "
    "usable resolution, and the resolution study (resolution7ftUntil2Long) "
    "takes 12, 18 and 27 cells.", ""]

# What the tutorial's box width shows over 10-40 s (study
# domain7ftTutorial)
DOMAIN_TUTORIAL_PROSE = [
    "The tutorial with its markers a cell apart in boxes 5.6, 8 and 11 "
    "D0 wide (12 cells "
    "across D0, from rest to 40 s, read over 10-40 s): C_D0 0.868, 0.865 "
    "and 0.869, descent 5.48 ± 0.09, 5.49 ± 0.07 and 5.48 ± 0.05 m/s, "
    "Dp/D0 0.800, 0.800 and 0.797, breathing at 1.23, 1.23 and 1.21 Hz "
    "with 16.0, 15.8 and 14.0 cm. The two widest boxes differ by 0.5 % "
    "in C_D0, under the 1 % the issue asks, but their combined 95 % "
    "interval is ±3.0 % (±2.5 % and ±1.6 %, twice the descent's "
    "relative half-widths), so the test shows the width's effect to be "
    "smaller than the 30 s window's own scatter, not that it is below "
    "1 %. The canopy's projected area blocks 0.8 % of the 8 D0 box's "
    "section and 0.4 % of the 11 D0 box's; Maskell's solid-wall "
    "estimate put the effect between 8 and 11 D0 at about 1 % (study "
    "domain7ft). The 11 D0 box costs 8 % more cells (51 156 against "
    "47 376: the widening falls on the coarsest level) and the same wall "
    "time (464 against 469 s on 2 ranks); the tutorial keeps 8 D0.", ""]

# What half the time step shows on the tutorial (study
# timeStep7ftTutorial)
TIME_STEP_TUTORIAL_PROSE = [
    "At 12 cells across D0 the tutorial's maxCo 0.5 sets steps of "
    "0.008-0.010 s in steady descent (median 0.0096 s, the largest "
    "Courant number 0.48-0.51 in nine steps of ten), just under its "
    "maxDeltaT 0.01 s, so this study halves both (maxCo 0.25, maxDeltaT "
    "0.005: 8 478 steps to 40 s against 4 201). Over 10-40 s: C_D0 "
    "0.863 against "
    "0.865 (-0.2 %), descent 5.50 ± 0.11 against 5.49 ± 0.07 m/s, Dp/D0 "
    "0.792 against 0.800, breathing at 1.12 Hz with 13.2 cm against 1.23 "
    "Hz with 15.8 cm. The step's effect on C_D0 is a tenth of the "
    "window's interval; the breathing's frequency moves by 9 %, the width "
    "of a few bins of its spectrum (0.033 Hz a bin over 30 s), and the "
    "half step converges the coupling in fewer iterations (2.16 against "
    "2.66 a step in steady descent, at most 3 against 5). 669 against 469 "
    "s on 2 ranks.", ""]

# What the cloth's resolution shows on the tutorial (study
# edgeLength7ftTutorial)
EDGE_TUTORIAL_PROSE = [
    "On the tutorial with its markers a cell apart (12 cells across D0, "
    "0.178 m cells) the "
    "fabric's edge at 1.25, 0.83 and 0.56 finest cells (0.222, 0.148 and "
    "0.100 m), each from rest to 40 s and read over 10-40 s, gives C_D0 "
    "0.865, 0.802 and 0.878 (descent 5.49 ± 0.07, 5.70 ± 0.12 and 5.45 ± "
    "0.11 m/s) and Dp/D0 0.800, 0.795 and 0.828. The levels oscillate: "
    "the 0.83 edge lies 7.3 % below the tutorial's, beyond the pair's "
    "combined 95 % interval (±5.0 %), and the 0.56 edge 9.5 % above the "
    "0.83 (±5.9 %), while the finest and the tutorial's edge are 1.5 % "
    "apart, inside theirs (±4.7 %). So at 12 cells the cloth's "
    "resolution moves C_D0 by up to about ±5 % about 0.85 without a "
    "trend, and the GCI above is the bound of that oscillation. The "
    "drag on the projected area, C_Dp, is 1.35, 1.27 and 1.28: the finer "
    "two agree to 1 % and differ in how far the canopy opens (Dp/D0 "
    "0.795 and 0.828, the skirt's radius 0.363 and 0.387 D0). Both finer "
    "cloths still speed up across the window (drifts +0.36 and +0.27 m/s "
    "against ±0.12 and ±0.11), so a longer window may move them. The "
    "breathing moves more: the tutorial's cloth breathes at 1.23 Hz with "
    "15.8 cm, the two finer cloths at 1.14 and 0.94 Hz with 1.3 cm each, "
    "a tenth of the amplitude, once the cloth is finer than the cells. "
    "The amplitude follows the edge against the cells, not the edge "
    "itself: at 27 cells the tutorial's ratio (1.25 finest cells, a "
    "0.099 m edge, as fine as the 0.56 edge here) breathes at 1.42 Hz "
    "with 19 cm (7ft-cpd27-bend0-cont, over 3-8 s of its continuation). "
    "The finer cloths converge the coupling in 2.99 and 2.34 iterations a "
    "step in steady descent (the tutorial's 2.66) and took 526 and 550 s "
    "on 2 ranks (469). On each marker's own force at 18 cells the same "
    "three edges oscillated too (0.674, 0.792 and 0.738: study "
    "edgeLength7ftLong).", ""]

# What the markers' spacing shows against the cloth's edge (study
# markers7ftTutorial)
MARKERS_TUTORIAL_PROSE = [
    "The markers sit at the centroids of each cloth triangle's "
    "sub-triangles (canopyMarkers: a triangle is split into 4^L until its "
    "longest edge is at most 1.5 times the spacing), so with the "
    "library's default, a spacing of one local cell, the tutorial's cloth "
    "(edge 1.25 finest cells) carries 372 markers on its 192 triangles "
    "(the larger split in four, the rest whole, their centroids up to "
    "about 0.7 cells apart) and the 0.83 edge 368 on 368: both 0.55 "
    "cells apart on average, where an immersed surface's markers are "
    "kept about half a cell apart so that the air does not leak through "
    "it (Olson & Layton, Contemp. Math. 628 (2014) p. 4). Each cloth's "
    "markers "
    "brought closer, the rest as it is (12 cells across D0, from rest to "
    "40 s, read over 10-40 s):", "",
    "| fabric edge [finest cells] | marker spacing | markers | C_D0 | "
    "descent [m/s] | Dp/D0 | breathing | wall time, 2 ranks |",
    "|---|---|---|---|---|---|---|---|",
    "| 1.25 (the tutorial's) | a cell (default) | 372 | 0.865 | 5.49 ± "
    "0.07 | 0.800 | 1.23 Hz, 15.8 cm | 7.8 min |",
    "| 1.25 | half a cell | 1 488 | 0.828 | 5.61 ± 0.08 | 0.810 | 0.82 "
    "Hz, 6.2 cm | 8.6 min |",
    "| 1.25 | a quarter of a cell | 5 952 | 0.826 | 5.62 ± 0.20 (drift "
    "-0.49) | 0.789 | 0.88 Hz, 6.4 cm | 14.5 min |",
    "| 0.83 | a cell (default) | 368 | 0.802 | 5.70 ± 0.12 (drift "
    "+0.36) | 0.795 | 1.14 Hz, 1.3 cm | 8.8 min |",
    "| 0.83 | half a cell | 1 472 | 0.822 | 5.63 ± 0.13 (drift +0.39) | "
    "0.800 | 0.95 Hz, 0.9 cm | 9.6 min |",
    "| 0.56 | a cell (default) | 768 | 0.878 | 5.45 ± 0.11 | 0.828 | "
    "0.94 Hz, 1.3 cm | 9.2 min |",
    "| 0.56 | a quarter of a cell | 5 328 | 0.894 | 5.40 ± 0.10 | 0.802 "
    "| 1.52 Hz, 0.6 cm | 16.5 min |", "",
    "On the tutorial's cloth the markers half a cell apart lower C_D0 by "
    "4.3 % (0.865 to 0.828), beyond the pair's combined 95 % interval "
    "(±3.8 %), and the breathing from 15.8 to 6.2 cm at 0.82 Hz (St "
    "0.25 against 0.38); a quarter of a cell changes C_D0 by -0.2 % "
    "more (0.826, its window still drifting) and the breathing not at "
    "all (6.4 cm): the markers converge from half a cell. The 0.83 "
    "cloth, whose markers were already about 0.55 cells apart, moves by "
    "+2.5 % (0.802 to 0.822), inside its ±6 %, and breathes 1 cm either "
    "way. With the markers converged the tutorial's cloth and the 0.83 "
    "cloth agree to 0.7 % (0.828 and 0.822, Dp/D0 0.810 and 0.800): the "
    "7 % between them in study edgeLength7ftTutorial was the markers' "
    "spacing, not the cloth's resolution, and so was most of the "
    "tutorial's 16 cm breathing. The 0.56 cloth stays apart: 0.878 with "
    "its own markers (768, 0.4 cells apart) and 0.894 with a quarter of "
    "a cell, 8.8 % above the 0.83 cloth's 0.822 with its markers "
    "converged, beyond the pair's ±5.7 %; so at 12 cells across D0 the "
    "cloth's finest step still moves C_D0 by about 9 %, the open "
    "question of the structure's resolution that remains. The tutorial "
    "now sets `forcing.markerSpacingCells 0.5` (the markers half a local "
    "cell apart; the library's default stays one cell, which the other "
    "tutorials keep until their own studies), at 10 % more wall time "
    "(516 against 469 s).", ""]

# What the tutorial's levels with the markers half a cell apart show
# (study resolution7ftMarkerHalf)
MARKER_HALF_PROSE = [
    "The tutorial as it is, its markers half a cell apart "
    "(`forcing.markerSpacingCells 0.5`, study markers7ftTutorial), from "
    "rest to 40 s at 12, 18 and 27 cells across D0 and read over 10-40 "
    "s; the 12-cell level is the main job. It restates for the tutorial "
    "as it is the converged value that study "
    "resolution7ftUndampedContinued made with the markers a cell apart "
    "(0.870 ± 1.6 %), and each 7 ft run's summary compared with it "
    "(report.py, convergedStudy) until the damped tutorial's levels "
    "(study resolution7ftDamped) were complete. The three levels give "
    "C_D0 0.828, 0.910 "
    "and 0.872 (5.61 ± 0.08, 5.35 ± 0.04 and 5.47 ± 0.03 m/s; Dp/D0 "
    "0.810, 0.807 and 0.803), breathing at 0.82, 1.29 and 1.33 Hz (St "
    "0.25, 0.42 and 0.42) with 6, 10 and 14 cm, and the descent speed "
    "at the same frequencies (0.85, 1.29 and 1.33 Hz, by 0.03, 0.07 and "
    "0.16 m/s: the payload feels the breathing), at 2.45, 2.58 and 2.23 "
    "coupling iterations a step. The 27-cell level (536 844 cells) took "
    "3.9 hours on 2 ranks, 5.4-6.4 minutes of wall time a simulated "
    "second, in parts each continued from the latest write. The 18- and "
    "27-cell levels are 4.4 % apart in C_D0, beyond the pair's combined "
    "±1.9 %, and the 27-cell level descends faster than the 18-cell one "
    "in each 5 s of 10-40 s (by 0.08-0.15 m/s), so the levels converge "
    "oscillatorily: 12 to 18 cells raise C_D0 by 9.9 %, 18 to 27 lower "
    "it by 4.2 %. Roache's GCI then takes the safety factor 3 with the "
    "IB forcing's formal first order (python/canopyfoam/gci.py) and gives "
    "C_D0 0.872 ± 26.1 %, the descent 5.47 m/s ± 12.6 %, Dp/D0 0.80 ± "
    "3.4 % (the table above): a wide bound because the 12- and 18-cell "
    "levels lie 10 % apart. The 27-cell level agrees with the converged "
    "value made with the markers a cell apart to 0.2 % (0.872 against "
    "0.870): the markers' spacing moves the coarse levels (12 cells: "
    "0.828 against 0.865) but not the finest. Against it the 12-cell main "
    "job is 5.05 % low, just outside issue 31's 5 % and inside the GCI "
    "(section \"The main job's resolution\"). Against Knacke's 0.75-0.80 "
    "for solid flat circular canopies (NWC TP 6575, Table 5-1) the "
    "27-cell level is 9 % above the range's top, and its Dp/D0 0.80 "
    "stands above the handbook's 0.67-0.70. The 40-cell level "
    "(7ft-cpd40-narrow-markerhalf-40s, the finest box 1.6 D0 wide, 0.86 "
    "M cells, about 16 400 steps at about 1.8 s a step: some 8 hours on "
    "2 ranks) was not carried through: the tutorial gained nylon's "
    "damping, and its 40-cell level is 7ft-cpd40-narrow-damped-40s "
    "(study levels7ftDamped's section). The main job's time step "
    "and coupling tolerance are in study numerics7ftMarkerHalf.", ""]

# What the three cloths show run on to 80 s (study
# edgeLength7ftTutorialTo80)
EDGE_TUTORIAL_80_PROSE = [
    "Run on from their 40 s writes to 80 s and read over 40-80 s, the "
    "three cloths keep what 10-40 s showed: C_D0 0.868, 0.805 and 0.878 "
    "(descent 5.48 ± 0.04, 5.69 ± 0.05 and 5.45 ± 0.04 m/s) against "
    "0.865, 0.802 and 0.878, now with 95 % intervals of 1.5-1.8 % in "
    "C_D0. The finer cloths' drifts over 10-40 s were their recovery "
    "from the first overshoot (over 40-80 s +0.14 and -0.10 m/s), and "
    "the oscillation of the levels is not the window's: the 0.83 edge "
    "lies 7.3 % below the tutorial's and the 0.56 edge 9.1 % above the "
    "0.83, each beyond the pair's combined interval. The cloth moves two "
    "things that compensate in C_D0 = C_Dp (Dp/D0)^2: the drag on the "
    "projected area falls monotonically with the edge, C_Dp 1.36, 1.26 "
    "and 1.20 (the second change 0.54 of the first; GCI 8.0 %, "
    "extrapolated 1.13), while the opening holds at Dp/D0 0.80 for the "
    "two coarser cloths and jumps to 0.85 for the finest, which still "
    "opens across the window (1.81 to 1.83 m). Flat circular canopies "
    "open to Dp/D0 0.67-0.70 (Knacke, Table 5-1), and the cloth without "
    "hoop stress to 0.676 under a uniform pressure jump (section \"The "
    "cloth's stiffness in compression\"): every cloth here stands "
    "wider, the finest widest, so at 12 cells across D0 the canopy's "
    "opening is what the structure's resolution leaves unconverged. The "
    "tutorial's cloth breathes at 1.19 Hz with 13 cm over 40-80 s, the "
    "finer two at 1.09 and 0.81 Hz with 1.1 and 1.7 cm. The 40 s "
    "extensions took 508, 577 and 734 s on 2 ranks (the totals from rest "
    "in the table). These cloths carry their markers a cell apart (the "
    "tutorial until study markers7ftTutorial): with the markers half a "
    "cell apart the 1.25 and 0.83 edges agree to 0.7 % over 10-40 s, and "
    "the 0.56 edge stays about 9 % above them.", ""]

# What the tutorial's levels with the dashpots until 2 s show (study
# resolution7ftUntil2)
UNTIL_TWO_PROSE = [
    "The hinge dashpots hold the slack cloth while the canopy first "
    "inflates (the projected diameter reaches 0.8 D0 by 1.5-2 s at every "
    "level) and are off after 2 s (`fabric.bendingDampingUntil 2`): from "
    "rest without them the 27-cell level stalls at 0.16 s (study "
    "resolution7ftUndamped), and left on they damp the breathing to a "
    "centimetre (section \"The 7 ft canopy's breathing against the "
    "cloth's edge and the hinge dashpots\"). Over 10-15 s the 12- and "
    "18-cell levels give C_D0 0.917 and 0.874, Dp/D0 0.800 and 0.810, "
    "breathing at 0.33 Hz (no breathing peak in the window) and 1.41 Hz "
    "(5.8 cm), in 2.1 and 2.3 coupling iterations a step; the 12-cell "
    "level read over 10-40 s gives 0.865 (study window7ft12): its 10-15 "
    "s value is the window's, and the GCI over 10-15 s measures the "
    "window as much as the mesh. The 27-cell level (536 844 cells) "
    "inflated with the dashpots at 2.31 coupling iterations a step and "
    "went on without them through the overshoot (6.09 m/s at 4-5 s, as "
    "the 18-cell level's 6.07-6.16 at 4-6 s) to 15 s, where from rest "
    "without the dashpots the same level stalled at 0.16 s. It was made "
    "in two parts (stopped at 5.7 s for time, continued from its 5.5 s "
    "write; 114 minutes on 2 ranks in all, partly beside other work). "
    "Over 10-15 s it gives 5.61 ± 0.05 m/s, C_D0 0.827, Dp/D0 0.809, "
    "breathing at 1.47 Hz (St 0.45) with 6.0 cm, at 1.96 coupling "
    "iterations a step (at most 10): the finest level of the tutorial's "
    "own set-up meets the issue's 2 iterations a step in steady descent. "
    "The three levels fall by about 5 % a refinement over 10-15 s (0.917, "
    "0.874, 0.827; the GCI table calls that divergent), where over 10-40 "
    "s the 12- and 18-cell levels rise (0.865, 0.893: study "
    "resolution7ftUntil2Long): the 10-15 s trend is the slow swing's "
    "phase at each level, not the mesh's, and the 27-cell level read over "
    "10-40 s is what will tell. Dp/D0 agrees to 0.2 % across the three.",
    ""]


MAIN_JOB_NOTES = ["## The main job's resolution", ""]
MAIN_JOB_NOTES += [
    "**Now** the main job runs the tutorial as it is, with nylon's "
    "material damping in the cloth and the lines (loss factor 0.02 at 2 "
    "Hz), on 12 cells across D0 from rest to 70 s, read over 30-70 s (run "
    "7ft-cpd12-damped-70s): C_D0 0.843, 5.56 ± 0.07 m/s, Dp/D0 0.80, in "
    "13.8 minutes on 2 ranks with mesh and report. Against the converged "
    "value of its own levels read over 40-80 s (study levels7ftDamped: "
    "the 27-cell level, C_D0 0.859 ± 27.4 %) it is 1.9 % low; its "
    "set-up read over the same window (7ft-cpd12-damped-80s, 0.851) is "
    "0.9 % low, and against the 27-cell level read over the main job's "
    "30-70 s (0.882) it is 4.3 % low: inside issue 31's 5 %. The bound is wide because the levels "
    "oscillate by about a 40 s window's statistical interval (that "
    "study's section). Against the same levels read over 10-40 s (study "
    "resolution7ftDamped, 0.894 ± 24.9 %), where the 12- and 18-cell "
    "levels still slow, it was 5.7 % low. The 18-cell level takes 61 "
    "minutes to 80 s, beyond the issue's 15, so the main job keeps 12 "
    "cells, and its summary states its error.", "",
    "**Before nylon's damping** the main job ran the tutorial of then "
    "(the hinge dashpots during the first inflation only, "
    "`fabric.bendingDampingUntil 2`; the markers half a cell apart, "
    "`forcing.markerSpacingCells 0.5`) on 12 "
    "cells across D0, from rest to 40 s, read over 10-40 s (run "
    "7ft-cpd12-markerhalf-40s): C_D0 0.828, 5.61 ± 0.08 m/s, Dp/D0 0.810, "
    "in 9.1 minutes on 2 ranks. Against the converged value of its own "
    "levels (study resolution7ftMarkerHalf: the 27-cell level, C_D0 0.872 "
    "± 26.1 %) it is 5.05 % low, just outside issue 31's 5 % and inside "
    "the GCI. The 18-cell level, 4.4 % above the 27-cell one, takes 64 "
    "minutes against the issue's 15, so the two conditions cannot both "
    "hold with the levels run: the main job keeps the setting within 15 "
    "minutes and its summary states the error. The cheapest level between "
    "12 and 18 cells, 13 (run 7ft-cpd13-markerhalf-40s, study "
    "mainJobLevel7ft), gives C_D0 0.811, 5.67 ± 0.16 m/s, in 12.1 "
    "minutes: 7.0 % low, further off than 12 cells (the levels oscillate: "
    "0.828, 0.811, 0.910 and 0.872 at 12, 13, 18 and 27 cells), and "
    "14 cells would take about 15.5 minutes by the 12- and 13-cell "
    "levels' cost (time ∝ cells across D0 to the power 3.6), so 12 cells "
    "stay. The 12-cell level to 15 s is cheaper (3.7 "
    "minutes) but its 10-15 s window reads the slow swing (study "
    "window7ft12). With the markers a cell apart the same set-up "
    "(7ft-cpd12-until2-40s, 7.8 minutes) gave 0.865, 0.6 % below the "
    "converged 0.870 ± 1.6 % of its own levels (study "
    "resolution7ftUndampedContinued). The paragraphs below are how the "
    "resolution was chosen before.", "",
    "**Until then** (the load taken from the cells, section \"The load is the "
    "reaction of the force in the cells\"; the stabiliser's balance seen "
    "through the kernel, section \"The stabiliser's balance seen through "
    "the kernel\"): the main job runs from rest to 15 s and is read over "
    "the last third, 10-15 s. Read over 8-12 s, as it was to 12 s, it "
    "took in the descent's dip after the overshoot: 5.17 ± 0.33 m/s with "
    "a drift of +0.90 (7ft-default-12s), where the same set-up run on "
    "holds at 5.36-5.54 m/s in every 2 s from 10 s to 40 s "
    "(7ft-default-40s). It finishes in 8.6 minutes on 2 cores, report "
    "included, at 1.39 coupling iterations a step (at most 7; 13.1 "
    "minutes and 2.17 with the balance of each triangle's mean, "
    "7ft-default-triangleMean): 5.55 ± 0.17 m/s over 10-15 s, C_D0 "
    "0.845, Dp/D0 0.793 (triangleMean: 5.42 ± 0.07, 0.889, 0.790). Its "
    "error against the converged value is in section \"The 7 ft "
    "canopy's resolution on the tutorial\"; what follows is "
    "how the resolution was chosen on each marker's own force.", "",
    "Issue 31 asks the main job (`./Allrun`: the 7 ft tutorial) to use "
    "the cheapest setting whose C_D0 is within 5 % of the converged "
    "value and that finishes within 15 minutes on 2 cores. With the "
    "tutorial as it is the converged value is taken from the study "
    "resolution7ftHeld: C_D0 0.714 with a GCI of 39.7 % (27 cells across "
    "D0, 5-12 s; oscillatory convergence, the 12-cell level a transient "
    "over that window); the main job's 0.685 over 8-12 s is 4.0 % below "
    "it, and 3.8 % below the 27-cell level read over the same 8-12 s. "
    "(With the coupling before the markers' relaxation the study "
    "resolution7ft gave 0.669 with a GCI of 4.9 %, which the 18-cell "
    "level repeated in steady descent: 0.684 over 30-43.9 s, study "
    "resolution7ftSteady.) "
    "On 12 cells across D0 the canopy settles into a more open state "
    "from about 9 s (C_D0 0.926 over 30-45 s, +38 %), which no finer "
    "level reaches; on 18 cells the descent holds at 6.1-6.35 m/s from "
    "3 s on. The tutorial therefore uses 18 cells across D0 from rest "
    "to 12 s, read over the last third, 8-12 s (run 7ft-default in the "
    "study default7ft, with its wall time). Every earlier 7 ft run that "
    "did not set its resolution restores 12 cells (`SEVEN_TWELVE` in "
    "python/canopyfoam/validation_runs.py).", ""]


KERNEL_FILTER_NOTES = ["## The stabiliser's balance seen through the "
                       "kernel", ""]
KERNEL_FILTER_NOTES += [
    "**Where the balance stalled.** The 0.044 m cloth of the mapped "
    "resolution levels (0.37 finest cells at 18 cells across D0), started "
    "from rest on the current coupling with the load from the cells, "
    "stopped at 0.15 s: from the tenth coupling iteration of a step the "
    "velocity residual was below 0.001 and the stabiliser's balance "
    "residual stayed at 0.0104 (0.0104 still after 40 iterations), "
    "against the tolerance's 0.005; with each marker's own force it "
    "stopped at 0.19 s the same way, and a mapped start of that cloth "
    "did not converge its second step in 40 iterations (balance "
    "0.006). The main job without the hinge dashpots stopped at 0.22 s "
    "with the balance at 0.0107 (section \"The load is the reaction of "
    "the force in the cells\"). Balanced by the step's mean "
    "acceleration instead of the last sub-step's (7ft-default-stepMean, "
    "study balance7ft) the fine cloth went on from 0.14 s in three "
    "iterations a step, but the main job stopped at 1.14 s (velocity "
    "residual 0.008), as the same change did on each marker's own force "
    "(3.39 s, section \"The long 7 ft runs' stop: a suspension line's "
    "vibration ...\").", "",
    "**Why.** The stabiliser gives every cloth node the added mass m_a "
    "(0.54 kg/m^2, 14 times the nylon's 0.0373) and balances it with m_a "
    "times the acceleration of the previous iteration. For a motion the "
    "air resists, the air's answer makes the iteration contract. For one "
    "it does not resist, the balance is a fixed point of the structure "
    "alone, reached by at best m_a/(m + m_a) = 0.94 an iteration, and "
    "with the structure in sub-steps balanced by the last sub-step's "
    "acceleration (endOfStep) the response of a stiff mode at the step's "
    "end oscillates with its phase: each iteration's balance then "
    "differs from the last by a residue that does not shrink. The air "
    "resists no motion finer than the IB kernel (three cells). The "
    "filter triangleMean gave no balance to the node-scale motions whose "
    "mean over every triangle is zero (section \"The stabiliser's "
    "filter: the node-scale modes keep their inertia\"); where the "
    "cloth's edge is a fraction of a cell, or without the dashpots that "
    "damp the fast motions within a step, the motions finer than the "
    "kernel span several triangles, which it still balanced.", "",
    "**The filter kernel** (`addedMass { filter kernel; }`, "
    "addedMassStabiliser.H, ibForcing::kernelMean). Each triangle's mean "
    "acceleration is put on its markers, averaged in each cell over the "
    "markers that spread into it (weights dV_m w_im), interpolated back "
    "to the markers and averaged over the triangle: what the IB kernel "
    "sees of it (ibStencil::shareSpread of dV_m a_m over the claims dV_m "
    "|w_im|, divided by dV_m). A uniform acceleration is kept where the "
    "weights are non-negative (tests/openfoam/ibInterpolation checks "
    "shareSpread's F = s c exactly), sum dV_m a_m is kept, and a motion "
    "finer than the kernel gets no balance: it keeps the mass m + m_a, an "
    "inertia at scales the air does not resolve, instead of a balance "
    "that does not converge. The balance residual measures the same "
    "filtered balance. The 7 ft tutorial uses it.", "",
    "| start | triangleMean | kernel |",
    "|---|---|---|",
    "| the 0.044 m cloth from its 0.14 s state (rest start), to 0.3 s "
    "| stalls at 0.15 s (balance 0.0104 after 40 iterations) "
    "| 47 steps in 1-4 iterations (16 / 16 / 9 / 6) |",
    "| the main job from rest, 0-2 s | 3.60 iterations a step (at most "
    "18); 5.111 m/s, Dp 1.621 m at 2 s | 2.43 (at most 7); 5.157 m/s, "
    "Dp 1.586 m |",
    "| the main job without hinge dashpots, 0-2 s | stops at 0.22 s "
    "(7ft-default-bend0) | 2.74 (at most 6); 4.925 m/s, Dp 1.816 m |",
    "", "These starts ran outside the study (the tutorial's case with the "
    "entries changed, `canopy-run-case`); the records of the main job "
    "with each filter and without the dashpots to 15 s are in study "
    "kernelFilter7ft. Over 10-15 s: filter kernel 5.553 ± 0.167 m/s, "
    "C_D0 0.845, Dp/D0 0.793, 1.39 iterations a step, 8.6 minutes; "
    "triangleMean 5.416 ± 0.072, 0.889, 0.790, 2.17, 13.1 minutes. "
    "**Without the hinge dashpots** (7ft-default-bend0-15s, filter "
    "kernel) the main job runs to 15 s at 2.47 iterations a step (at "
    "most 6; 15.7 minutes): 5.449 ± 0.12 m/s, C_D0 0.878, Dp/D0 0.807, "
    "inside the resolution study's GCI of the dashpots' run, and the "
    "fold angles between neighbouring triangles are those of the damped "
    "cloth (3.6 / 6 / 14 / 20 / 30° from crown to skirt against 3.8 / "
    "6.3 / 13 / 17 / 32°): no cell-scale flapping. The canopy then "
    "breathes: 1.39 Hz (St 0.44) with 81 mm amplitude over 7 periods, "
    "where the damped main job's largest peak is 11 mm at 0.46 Hz; the "
    "drop test breathes visibly at about 2 Hz. The dashpots (10 000 /s) "
    "froze the breathing; whether the tutorial drops them (its cost "
    "would pass 15 minutes) is for the studies that follow.", ""]


UNDAMPED_CONTINUED_PROSE = [
    "Continued without the hinge dashpots from their damped runs' "
    "canopies at 15 s, the 12-, 18- and 27-cell levels give C_D0 0.864, "
    "0.872 and 0.870 (Dp/D0 0.829, 0.793 and 0.787) in about 2 coupling "
    "iterations a step (2.03, 2.08 and 1.95; the 27-cell level 45 min for "
    "8 s on 2 ranks), within 1 % of the 12- and 18-cell levels without "
    "them from rest (0.873 and 0.878, study resolution7ftUndamped), where "
    "the damped levels give 0.822, 0.845 and 0.826. The breathing's "
    "frequency stays at 1.28-1.42 Hz (St 0.41-0.46), while its amplitude "
    "grows with the resolution, 4.3, 16.5 and 19.3 cm of the projected "
    "diameter. Roache's GCI of the 27-cell level (the table above): C_D0 "
    "0.870 ± 1.6 %, the descent 5.47 m/s ± 0.8 %, Dp/D0 0.787 ± 4.7 %, "
    "against 14.3, 7.0 and 10.9 % for the damped levels from rest. "
    "Against "
    "Knacke's 0.75-0.80 for flat circular canopies the undamped canopy's "
    "C_D0 is about 9 % above the range's top.", ""]

BREATHING_CLOTH_PROSE = [
    "With the hinge dashpots (the tutorial's 10 000 /s) the canopy on the "
    "cloth of 0.222 and 0.148 m edges does not breathe: the peaks at 0.50 "
    "and 0.46 Hz (St 0.15) are 3.4 and 1.1 cm over two periods of a 5 s "
    "window, the descent's slow wander rather than a breathing. On the "
    "0.099 m cloth of the 27-cell level it breathes at 1.66 Hz, and on "
    "the 0.044 m cloth of the mapped levels at 1.25-1.37 Hz with the same "
    "dashpots. Without them it breathes on the coarse cloth too: 1.25 and "
    "1.39 Hz with 7.1 and 8.1 cm at 12 and 18 cells across D0 (St 0.39 and "
    "0.44, 6-7 periods), and the two levels agree closely in the rest: "
    "C_D0 0.873 and 0.878 (+0.6 %), Dp/D0 0.806 and 0.807, where the "
    "damped levels give C_D0 0.822, 0.845 and 0.826 at 12, 18 and 27 "
    "cells.", "",
    "Why the dashpots' effect depends on the cloth: a hinge dashpot of "
    "rate R damps a smooth bending of wavenumber k on edges h at about "
    "R (k h)^4 (libcanopy's bending.c; tests/canopy/"
    "test_bending_damping_scale.c measures it), so the same physical "
    "shape change is damped 5 times less on the 0.099 m cloth than on the "
    "0.148 m one and about 130 times less on the 0.044 m one. The "
    "dashpots are a regularisation of the structure's discretisation, "
    "not a material property: their effect vanishes as the cloth is "
    "refined, so the converged canopy is the undamped one, and at the "
    "main job's cloth they freeze the breathing that the finer cloths "
    "show. Nylon's own damping (the section \"7 ft canopy: nylon's "
    "material damping as Kelvin-Voigt dashpots\", loss factors 0.01-0.1) "
    "is a separate, physical term.", "",
    "The drop test's canopy breathes at about 2 Hz (St ≈ 0.75 at 4.27 "
    "m/s and about 1.6 m across; Kim 2012, sec. 5.7); the model's "
    "breathing, where it is resolved, lies at 1.25-1.66 Hz (St 0.39-0.51). "
    "From rest without the dashpots the 27-cell level stops at 0.16 s "
    "while the canopy starts to inflate (7ft-cpd27-bend0-15s): the "
    "interface's velocity converges (residual 0.0034) but the "
    "stabiliser's balance stays at 0.010-0.013 through 20 iterations "
    "(tolerance 0.005). Balanced by the step's mean acceleration "
    "(addedMass.balance stepMean) the same case, continued from its last "
    "good state, passes that step but takes 5 iterations a step and stops "
    "the same way at 0.45 s (build/exp, not a study run). So the "
    "inflation of the finer cloth from rest still needs the dashpots; "
    "the inflated canopy does not: each level continued without them "
    "from its damped run's canopy at 15 s (study "
    "resolution7ftUndampedContinued) runs at about 2 iterations a step. "
    "Without them the coupling takes 2.0-2.9 iterations a step against "
    "1.3-1.4, and the main job at 18 cells from rest 15.7 min against "
    "8.6.", ""]


PRESSURE_LOAD_NOTES = ["## The pressure load within a step", ""]
PRESSURE_LOAD_NOTES += [
    "The main job in a box 11 D0 wide (`7ft-default-follower-w11`), with "
    "the pressure jump's load following the cloth within the structure's "
    "sub-steps as libcanopy applied it then, stopped at 8.06 s: in the "
    "17th HHT sub-step of one fluid step a skirt node passed the speed "
    "limit of 100 m/s. 7ft-cpd18-45s stopped the same way at 43.94 s. "
    "Restarted from the written state before the stop (16 s on 2 ranks), "
    "each stops at the same sub-step; with the limit at 1e4 m/s the node "
    "reaches 12 779 m/s in that step, a runaway, not a fast physical "
    "motion. Halving the sub-steps (Lambda dt <= 1, `7ft-default-omega1`) "
    "moved the stops, not removed them: at 2.82 s in the 11 D0 box and at "
    "7.21 s in the 5.6 D0 box (`7ft-default-omega1-w11`, `-w5.6`), while "
    "the 8 D0 box ran through. With the speed limit at 10 m/s the "
    "restart stops in the step's first coupling iteration, with the air's "
    "load fixed, when node 178 passes 10 m/s in sub-step 36 of 39: the "
    "structure runs away under a given load. Node 178 is a skirt node "
    "whose spring to node 140, one ring in, had shortened to 0.1 % of its "
    "rest length: the two nodes were passing through each other, a "
    "triangle of the gathered skirt folding over. libcanopy applied the "
    "pressure jump as dp A n / 3 on each triangle's current shape in every "
    "sub-step, a follower load: once a triangle has folded over, its "
    "normal, and the load with it, points the other way, and the load "
    "pushes the triangle further over. The air cannot see such a fold (it "
    "is finer than the cells) and computed the load once for the step.",
    "",
    "Restarts from the four written states before the stops, each to "
    "about 0.5 s past its start (2 ranks, the build of this change; the "
    "descent speed at the end):",
    "",
    "| change | 11 D0, Lambda dt 2, from 8 s | 11 D0, Lambda dt 1, from "
    "2.75 s | 5.6 D0, Lambda dt 1, from 7 s | 7ft-cpd18-45s, from 43.75 "
    "s |",
    "|---|---|---|---|---|",
    "| none | stops at 8.0667 s | stops at 2.8214 s | stops at 7.2056 s | "
    "stops at 43.939 s |",
    "| hinge dashpots 1e5 /s (10 times the tutorial's) | | runs to 3 s | "
    "| |",
    "| fabric.compressionRatio 0.01 | runs to 8.1 s (4.1 iterations a "
    "step) | | | |",
    "| the whole IB reaction as fixed nodal forces (pressure jump 0) | "
    "runs, 5.86 m/s | runs, 5.91 | runs, 5.81 | runs, 5.82: the descent "
    "falls because the cloth's porosity is driven by the pressure jump, "
    "which this turned off |",
    "| pressure jump's load held over the step (pressureHeld) | runs, "
    "6.09 m/s, 1.10 iterations a step | runs, 6.06 m/s, 1.39 | runs, 6.06 "
    "m/s, 1.12 | runs, 6.33 m/s, 1.28 |",
    "",
    "libcanopy therefore takes the pressure jump's load on the shape at "
    "the start of each step or advance and holds it over its sub-steps "
    "when asked (`canopy_model_set_pressure_frozen`; "
    "tests/canopy/test_pressure_frozen.c), and canopyFoam asks for it "
    "with `coupling.load.pressureHeld true`, which the 7 ft tutorial "
    "sets. Across steps the load still follows the cloth: the air "
    "computes it on the markers where the cloth is. The pressure jump "
    "itself is unchanged, and so is the porosity that it drives. Every "
    "earlier 7 ft run restores the follower load (`SEVEN_FOLLOWER` in "
    "python/canopyfoam/validation_runs.py); the study pressureLoad7ft "
    "compares "
    "the main job with both, and the domain study domain7ft is made with "
    "the held load.", ""]


STABILISER_FILTER_NOTES = ["## The stabiliser's filter: the node-scale "
                           "modes keep their inertia", ""]
STABILISER_FILTER_NOTES += [
    "**Why the apex's cloth vibrated.** A one-node model of the "
    "stabilised step without air (python/canopyfoam/stabiliser_model.py: "
    "a node of mass m on a spring k with the stabiliser's m_a, integrated "
    "exactly over a step dt under a balancing force m_a a(dt) of the "
    "previous iteration, K iterations a step, predictor zero) grows "
    "wherever m_a > m and the mode is stiff against the step: with "
    "theta = sqrt(k/(m + m_a)) dt and mu = m_a/(m + m_a),", "",
    "| mu (m_a/m) | first growing theta, K = 2 / 4 / 6 / 20 iterations | largest growth a step, K = 2 / 6 |",
    "|---|---|---|",
    "| 0.5 (1) | none / none / none / none | 1.000 / 1.000 |",
    "| 0.8 (4) | 1.83 / 2.30 / 2.57 / none | 1.181 / 1.011 |",
    "| 0.935 (14.4, the 7 ft cloth) | 1.65 / 1.98 / 2.19 / 2.70 | 1.309 / 1.065 |", "",
    "With one iteration the balance is zero and the step is the exact "
    "oscillator's; converged (K large) it does not grow either; in "
    "between, a balance that has converged only by (mu cos theta)^K "
    "pumps energy into the mode. The step-mean balance grows even when "
    "converged (2.58 a step at theta 1.75). The 7 ft cloth's springs "
    "give theta of about 10 at 18 cells (the nodes' frequency bound "
    "4800-6200 /s on their own mass, dt 7.6 ms, 15.5 times the mass), so "
    "every cloth mode the air does not resist is in that range. The "
    "air does not resist the node-scale modes: the IB kernel spreads "
    "each marker's force over three cells, wider than a triangle (edge "
    "0.13-0.20 m at 18 cells, cells of 0.12 m). On 12 cells the steps "
    "converge at their first iteration (K = 1, neutral); on 18 cells "
    "they take 2-6, and the cloth next to the apex, where the triangles "
    "are smallest, grew first.", "",
    "**The filter.** `addedMass { filter triangleMean; }` "
    "(src/canopyFoam/coupling/addedMassStabiliser) makes the balancing "
    "force of each triangle's mean acceleration, a third of the "
    "triangle's added mass m_A A_t to each of its nodes: the same total "
    "force and the same force for a uniform acceleration as before, none "
    "for a motion whose mean over every triangle is zero. Those modes "
    "keep the lumped mass m + m_a unbalanced, as an inertia (the model's "
    "`seen = 0`: neutral for every K and theta; a mode the balance sees "
    "by a share s grows only when s mu exceeds about 0.53).", "",
    "| check | without the filter | with it |",
    "|---|---|---|",
    "| structure alone, the HHT tutorials' scheme, 6 iterations a step "
    "of 0.01 s, predictor zero (tests/openfoam/addedMassStabiliser) "
    "| energy gain 1.3e-3 J by 2 s (kinetic energy 3.7e-4 J in the "
    "first tenth); a node passes 100 m/s after 237 steps "
    "| no gain in 400 steps, kinetic energy at most 3.7e-4 J |",
    "| 18 cells across D0, coupling to 1e-3, restarted at 1.5 s (apex "
    "nodes at 0.7 m/s) | 10.3 m/s at 2 s, stopped at 2.11 s (40 "
    "iterations), 5.0 iterations a step | 0.0 m/s from 1.75 s, to 2.6 s "
    "at 1.57 iterations a step |",
    "| 12 cells (the main job), from rest to 8 s, predictor zero | 1.23 "
    "iterations a step, 5.62 m/s over 5-8 s | 1.56, 5.64 m/s over "
    "5.33-8 s |", "",
    "On 12 cells with the filter the lagging predictors run too (from "
    "rest to 8 s, the apex's cloth below 0.7 m/s): `lastStep` at 2.04 "
    "iterations a step, `lastStepMean` at 2.73 (5.675 m/s over 5.33-8 "
    "s); the model says a lag still grows the modes the balance sees "
    "where the air does not resist them, so the tutorial keeps `zero`. "
    "With the filter the balance cancels the lumped added mass at "
    "convergence only for the smooth motion: the test's balanced check "
    "(one HHT step a time step, a 2 Pa step load, the balance converged "
    "to 1e-10) moves the cloth 5.2 % of its displacement away from the "
    "structure without the stabiliser, against 7e-12 m unfiltered. "
    "`addedMass { distribution consistent; }` puts the same "
    "triangle-mean matrix, sum over t of (m_t/9) 1_t 1_t^T, into the "
    "structure's equation instead of the lumped mass (libcanopy's "
    "canopy_model_set_triangle_added_mass, in HHT's residual, Jacobian "
    "and start-up acceleration): the node-scale modes then carry no "
    "added mass, and the balanced check gives 5.8e-12 m "
    "(tests/openfoam/addedMassStabiliser, balanced-consistent). On the "
    "7 ft case it gives the lumped filter's answer on 12 cells (from "
    "rest to 8 s: 5.61 ± 0.12 m/s over 5-8 s, C_D0 0.830, 1.37 "
    "iterations a step) and runs the 18-cell restart from 1.5 s to 2.6 "
    "s with the apex's cloth quiet, but at 2.93 iterations a step "
    "instead of 1.57 and 33 structure sub-steps instead of 24 (the "
    "node-scale modes, without the added mass, are faster and take "
    "their load's changes at once); the tutorial keeps the lumped "
    "filter. Without air, in the HHT tutorials' sub-steps with 2 "
    "iterations a step, the smooth modes still grow either way (the "
    "one-node model's seen = 1); with 6, `zero` is stable with both. "
    "The large canopies keep one HHT step per time step with "
    "`lastStep` and no filter, the scheme of their records.", "",
    "What moved: the main job of then (`7ft-stiff` now, re-made) descends at 5.62 "
    "± 0.09 m/s (95 %) over 5-8 s, C_D0 0.824, projected diameter 1.90 "
    "m, in 2.4 minutes at 1.37 coupling iterations a step (before: 5.62 "
    "± 0.09, 0.826, 1.90 m, 2.1 minutes, 1.23). The 8-cell case of "
    "tests/foamRun/flatCircular7ft descends at 3.298 m/s at 2 s at 2.89 "
    "iterations a step (3.252 and 3.15 before).", ""]

# foamRun on OpenFOAM-12 against canopyPimpleFoam on v1912 (tests/foamRun),
# measured by hand in an OpenFOAM-12 shell: CI has no OpenFOAM-12
FOAMRUN_NOTES = ["## foamRun on OpenFOAM-12 (canopyFluid) against "
                 "canopyPimpleFoam", ""]
FOAMRUN_NOTES += [
    "The solver module `applications/modules/canopyFluid` under `foamRun` "
    "on OpenFOAM-12 (Foundation, commit 0b487fc, built at -O1) against "
    "`canopyPimpleFoam` on OpenFOAM v1912 (Debian), the same case "
    "directories and the same coupling library. The v1912 values are "
    "`tests/foamRun/*/canopyPimpleFoam.ref`, kept current by the v1912 "
    "test `openfoam/foamRunReferences`; the OpenFOAM-12 values come from "
    "`./Alltest foamRun/` in a shell that has sourced OpenFOAM-12 "
    "(`source <OpenFOAM-12>/etc/bashrc; export CANOPYFOAM_DIR=$PWD; "
    "./Allwmake`).", "",
    "| case | canopyPimpleFoam (v1912) | foamRun (OpenFOAM-12) | "
    "difference | tolerance |",
    "|---|---|---|---|---|",
    "| porous plate, pressure drop at 0.2 m/s | 50.0181 Pa | 50.0181 Pa | "
    "0 | 0.5 % |",
    "| porous plate, 0.5 m/s | 125.575 Pa | 125.575 Pa | 0 | 0.5 % |",
    "| porous plate, 1.0 m/s | 252.712 Pa | 252.713 Pa | 4e-6 | 0.5 % |",
    "| 7 ft canopy, 8 cells across D0, descent at t = 2 s, 1 rank | "
    "4.27872 m/s (3.92 coupling iterations a step) | 4.28782 m/s "
    "(4.129) | 2.1e-3 | 1 % |",
    "| the same on 2 ranks | 4.27902 m/s (3.91) | 4.28827 m/s (4.134) | "
    "2.2e-3 | 1 % |",
    "| restart from 0.5 s to 1 s, 1 and 2 ranks (`tests/foamRun/restart`)"
    " | byte for byte | byte for byte | - | exact |",
    "| a failing step (`tests/foamRun/lastGoodState`: speed limit 2 m/s) "
    "| stops at 0.57 s, writes 0.56 s, a restart runs on to 0.76 s | the "
    "same | - | - |",
    "| PIMPLE set-ups the coupling cannot end the loop under "
    "(`tests/foamRun/setUpErrors`: 5 variants) | - | each refused at the "
    "start, naming the entry | - | - |", "",
    "The rows are from code cf852ba (the 7 ft tutorial's cloth without "
    "stiffness in compression, `fabric.compressionRatio 0`) built on "
    "OpenFOAM-12: `./Alltest foamRun/` 5 passed, 0 failed. The whole "
    "`./Alltest` in the OpenFOAM-12 shell last ran at c60c80b: 82 "
    "passed, 0 failed (the C, Python and ParaView tests, the "
    "verification cases and the seven tutorials for three steps under "
    "foamRun, the foamRun tests; the 17 tests/openfoam tests that need "
    "canopyPimpleFoam skipped with one line).", ""]
FOAMRUN_NOTES += [
    "The two solvers run the same coupling, structure and face-force "
    "numerics; what differs is OpenFOAM's: foamRun grows the time step by "
    "up to `deltaTFactor` (1.2) a step where canopyPimpleFoam's setDeltaT "
    "grows it more gently, and the linear solvers and the 2-rank "
    "agglomeration are OpenFOAM-12's. The porous plate reaches a steady "
    "state, where those differences vanish; the 7 ft canopy is still "
    "accelerating at 2 s (2.7 m/s at 1 s), where a difference in the "
    "time steps would show in its descent. Under foamRun the coupling ends "
    "the outer loop through PIMPLE's `outerCorrectorResidualControl`: "
    "the iteration after the coupling has converged solves nothing "
    "(`canopyFluid.H`). With the stabiliser started from zero in each "
    "step and unfiltered (code c60c80b) foamRun took 3.39 coupling "
    "iterations a step against 3.15 and descended 0.47 % slower at 2 s; "
    "with the filter both took 2.891 and agreed to 6e-6 (code ce0df0d, "
    "the stiff cloth). With the cloth without stiffness in compression "
    "the steps take more iterations, 3.9 under v1912 against 4.13 under "
    "foamRun, and the two no longer follow the same iterations: foamRun's "
    "descent at 2 s is 0.21 % faster, within the 1 % the time steps "
    "allow.", ""]


# The prose that closes each study of the tutorial's set-up, after its
# tables
# What half the time step and the coupling's tolerance do to the main
# job (study numerics7ftMarkerHalf)
NUMERICS_MARKER_HALF_PROSE = [
    "The main job's numerics, each change against the main job over the "
    "same window; the 95 % interval of C_D0 is twice the descent's "
    "relative half-width, and a pair's combined interval the root sum of "
    "squares of its two. Over 10-40 s from rest: half the time step "
    "(maxCo 0.25, maxDeltaT 0.005; 8 903 steps against 4 297) gives C_D0 "
    "0.796 against 0.828 (-3.9 %, inside the pair's ±7.0 %: the half "
    "step's descent still drifts by -0.41 m/s over the window), Dp/D0 "
    "0.818 against 0.810 and a breathing of 2.9 cm against 6.2 at 0.86 "
    "and 0.82 Hz, at 2.47 coupling iterations a step (max 3) against "
    "2.58 (max 6). The coupling's tolerance doubled to 1e-2 gives 0.799 "
    "(-3.5 %, inside ±4.1 %) at 2.03 iterations a step. Halved to 2.5e-3 "
    "from rest, the coupling first did not converge in 20 iterations as "
    "the canopy inflated (0.9 s): IQN-ILS's second iteration raised the "
    "residual from 0.028 to 0.68 and it stayed above 0.05 (section "
    "\"Coupling design notes\", IQN-ILS when the past steps mislead it). "
    "With the past steps' columns dropped after such an update (three "
    "times, at 0.64 and 2.09 s) it runs to 40 s in 10.1 minutes at 2.96 "
    "iterations a step (max 9) and gives 0.805 (-2.8 %, inside ±3.1 %; "
    "5.69 ± 0.04 m/s, Dp/D0 0.810, breathing 5.3 cm at 0.95 Hz). Going "
    "on from the main job's 40 s write, over 40-80 s: 2.5e-3 gives 0.873 "
    "against the main job's own 0.852 (+2.5 %, inside ±4.3 %; 3.34 "
    "iterations a step, max 7, 676 s against 604 s for the 40 s). No "
    "change moves C_D0 beyond its pair's interval, and the tolerance's "
    "three values over 10-40 s do not order (0.799, 0.828 and 0.805 at "
    "1e-2, 5e-3 and 2.5e-3), so the differences are the window's: each "
    "run meets the descent's slow swing in another phase. The levels of "
    "the resolution study run at the tutorial's 5e-3. The main job's own "
    "two windows differ by +2.9 % (0.828 over 10-40 s, 0.852 over 40-80 "
    "s, inside ±3.5 %; descent 5.61 ± 0.08 and 5.53 ± 0.06 m/s, the "
    "second still drifting by -0.23 m/s): at 12 cells the descent slows "
    "over 80 s by about as much as any of these changes moves it.", ""]

# What the quasi-Newton history does to the coupling's iterations (study
# quasiNewtonReuse7ft)
QN_REUSE_PROSE = [
    "Over the same 1.5 s (157 steps, from the same write), IQN-ILS "
    "reusing the columns of 8, 0 and 16 past steps takes 2.80, 2.91 and "
    "2.81 coupling iterations a step, C_D0 0.860, 0.859 and 0.859. The "
    "residual's mean falls the same way in each: 0.021-0.022 after the "
    "first solve, 0.0070-0.0076 after the second, 0.0019-0.0020 after "
    "the third, about a third an iteration, so the second solve lands "
    "just above the tolerance of 5e-3 in eight steps of ten and the "
    "third below it. The history IQN-ILS keeps does not carry that "
    "reduction: the first solve's residual is the interface velocity's "
    "change over the step (0.02 of Uref 4 m/s, 0.09 m/s rms over the "
    "cloth), which a step's history does not predict; a first iterate "
    "extrapolated linearly from the last two steps (tried on the same "
    "1.5 s and not kept) raised it to 0.034 (3.06 iterations a step), "
    "so that change "
    "is not smooth from step to step. On 18 cells the residuals are "
    "the same, 0.025, 0.008 and 0.002 (7ft-cpd18-markerhalf-40s, 2.81 "
    "iterations a step): the count grows with the resolution because "
    "the second solve's residual sits at the tolerance, not because "
    "the iteration converges more slowly. Issue 31's target of 2 "
    "iterations a step is met only with the tolerance at 1e-2 (study "
    "numerics7ftMarkerHalf: 2.03, C_D0 -3.5 %).", ""]

# What sets the 7 ft tutorial's coupling iterations in steady descent
# (study iterations7ft)
ITERATIONS_7FT_PROSE = [
    "The tutorial's cloth and lines carry dashpots of loss factor about "
    "5e-5 (the hinge dashpots are off from 2 s), so nothing damps their "
    "in-plane elastic waves: a membrane wave in the cloth, sqrt(E t / "
    "rho_s) = sqrt(2919 / 0.0373) = 280 m/s, crosses a gore (0.42 m "
    "at the skirt) in 1.5 ms, within the fluid's step of 9-10 ms. Written every "
    "step over 41.5-41.65 s, the tutorial's cloth changes its velocity by "
    "0.070 m/s rms from one step to the next (0.040 along the normal, "
    "0.058 in the cloth's plane), and consecutive changes are "
    "anticorrelated (-0.19, in the plane -0.33): a vibration the steps "
    "alias, not a motion the last step foretells. The forcing imposes the "
    "whole velocity (tangential noSlip), so the first iteration's "
    "residual is that change, about 0.02 of Uref = 4 m/s, four times the "
    "tolerance; the second lands at 0.006-0.007, above it in eight steps "
    "of ten (study quasiNewtonReuse7ft), hence 2.8 iterations a step. A "
    "first iterate extrapolated from the last two steps made the first "
    "residual larger, as anticorrelated changes predict (study "
    "quasiNewtonReuse7ft).",
    "",
    "Nylon's material damping as Kelvin-Voigt dashpots on every cloth "
    "and line spring (nylon_damping: c = eta k / omega at 2 Hz) removes "
    "that vibration. Going on from the main job's 40 s write, within "
    "0.2 s the first iteration's residual falls from 0.021 to 0.005 "
    "(loss factor 0.02) and 0.004 (0.1), and over 40-41.5 s the coupling "
    "takes 1.62 and 1.30 iterations a step (1.53 and 1.15 from 40.25 s) "
    "against the tutorial's 2.80. Written every step from 41.5 s, the "
    "damped cloth (0.02) changes by 0.011 m/s a step, six times less, "
    "and smoothly (correlation +0.65), in 1.00 iteration a step. C_D0 "
    "over the 1.5 s, 0.876 (0.02) and 0.870 (0.1) against 0.860, moves "
    "by less than the window's interval (about ±3.6 %, twice the "
    "descent's ±0.10 m/s). The lines' interior nodes go on changing by "
    "0.53-0.62 m/s a step with or without the damping (correlation "
    "-0.3 to -0.6): a dashpot along a line segment does not resist the "
    "line's transverse vibration, whose stretch is of second order; the "
    "lines carry no air load here (lineDrag off), so it does not reach "
    "the coupling. No measured loss factor of parachute nylon near these "
    "frequencies was found to cite: polymers' loss factors span 0.01-2 "
    "(Gerdeen, Lord & Rorrer, Engineering Design with Polymers and "
    "Composites, ch. 12), nylon's modulus depends strongly on the "
    "frequency it is measured at (Lynch-Aird & Woodhouse, Materials 10 "
    "(2017) 497), and a guitar string's material damping, measured in a "
    "vacuum, grows about linearly with frequency, as a viscous dashpot's "
    "does (J. W. Christian, \"Parameter estimation of multiple non-linear "
    "damping sources in guitar strings\", Savart Journal, 2011); 0.02 is "
    "the bracket's low end. Study "
    "damping7ftTutorial runs the main job from rest with it.", ""]

# What nylon's material damping does to the main job (study
# damping7ftTutorial)
DAMPING_7FT_TUTORIAL_PROSE = [
    "Nylon's material damping at a loss factor of 0.02 at 2 Hz (study "
    "iterations7ft says why) in the main job from rest: over 10-40 s C_D0 "
    "0.768 against the tutorial's 0.828, but the damped canopy is still "
    "slowing across the window (drift -0.67 m/s; 5-s means 6.14, 5.98, "
    "5.85, 5.69, 5.79 and 5.52 m/s from 10 s, where the undamped one "
    "levels at 5.5-5.7 from 10 s), so the pair is not told apart there "
    "(±8 %). On to 80 s and read over 40-80 s, where both have settled, "
    "the damped main job descends at 5.59 ± 0.04 m/s against 5.53 ± 0.06: "
    "C_D0 0.835 against 0.852 (-2.0 % ± 2.5 %, inside the pair's "
    "interval), Dp/D0 0.799 against 0.814, crown height 0.221 against "
    "0.219 D0, skirt radius 0.367 against 0.369 D0: the damping moves "
    "neither the steady descent nor the shape beyond the window's "
    "uncertainty. It moves the breathing: the diameter's spectrum peaks "
    "at 0.34 Hz (5.7 cm, at the band's edge) against 0.75 Hz (6.7 cm), "
    "the descent speed's at 0.84 against 0.99 Hz. And it halves the "
    "coupling's work: 1.15 iterations a step over 10-40 s and 1.28 over "
    "40-80 s against 2.58 and 2.86; from rest to 40 s in 5.0 minutes "
    "against 9.1 and the 40-80 s part in 339 s against 604 s on 2 ranks, "
    "each alone on the machine.",
    "",
    "At 18 cells across D0 (10-40 s) the damping moves C_D0 beyond the "
    "pair's interval: 0.839 against 0.910 (descent 5.57 ± 0.09 against "
    "5.35 ± 0.04 m/s, -7.8 % ± 3.5 %), Dp/D0 0.798 against 0.807, crown "
    "height 0.247 against 0.240 D0, at 1.10 iterations a step against "
    "2.81, in 22.6 minutes against 64 on 2 ranks. The damped canopy "
    "approaches its steady descent more slowly here too (5.76 m/s over "
    "10-15 s, 5.49-5.57 from 15 s; drift -0.23 m/s). Its breathing "
    "keeps its frequency and loses its amplitude: 1.19 Hz with 1.6 cm "
    "against 1.29 Hz with 10 cm. The damped levels lie close together, "
    "0.835 at 12 cells (40-80 s) and 0.839 at 18 (10-40 s), where the "
    "undamped ones move from 0.852 to 0.910: the cloth's undamped "
    "vibration is part of what the undamped levels' oscillation (study "
    "resolution7ftMarkerHalf, GCI ±26 %) measures. Study "
    "resolution7ftDamped carries the damped levels to 27 cells. (Read "
    "over the same 40-80 s, study levels7ftDamped, the damped levels part "
    "again: 0.851 at 12 cells and 0.898 at 18, the 18-cell canopy still "
    "slowing after 40 s; the closeness above was the windows'.)", ""]

# The damped tutorial's levels (study resolution7ftDamped)
RESOLUTION_DAMPED_PROSE = [
    "With nylon's damping (loss factor 0.02 at 2 Hz) the three levels "
    "from rest read over 10-40 s give C_D0 0.768, 0.839 and 0.894 at 12, "
    "18 and 27 cells across D0 (5.83, 5.57 and 5.40 m/s; Dp/D0 0.802, "
    "0.799 and 0.810), at 1.15, 1.12 and 1.17 coupling iterations a step, "
    "issue 31's 2 met at every level. The levels converge monotonically "
    "in C_D0 and the descent, so Roache's GCI takes the observed order "
    "with safety factor 1.25 (the table above): C_D0 0.894 ± 24.9 % "
    "(observed order 0.66), the descent 5.40 m/s ± 8.6 % (0.94), Dp/D0 "
    "0.81 ± 8.8 % (oscillatory, safety factor 3). The order below the "
    "forcing's formal first order comes from the coarse levels still "
    "slowing across the window (drift -0.67 m/s at 12 cells, -0.23 at "
    "18), whereas the 27-cell level holds steady over 20-40 s: its 5-s "
    "means over 10-40 s are 5.55, 5.45, 5.36, 5.31, 5.36 and 5.36 m/s "
    "(after 40 s it wanders by ±3 %, study levels7ftDamped). Read over "
    "10-20 s the same levels give 0.710, 0.811 and 0.862 with the change "
    "halving per level: the window, not only the resolution, sets the "
    "coarse levels' values, which is why study levels7ftDamped reads "
    "them over 40-80 s (12 cells 0.851, 18 cells 0.898) and took this "
    "level on from its 40 s write to 80 s (0.859). The shape converges "
    "sooner "
    "than the drag: the 18- and 27-cell levels stand their crown 0.247 "
    "D0 above the skirt and show a silhouette of 0.751 and 0.752 D0 "
    "(the shape table). The 27-cell level breathes at 1.26 Hz (St 0.40) "
    "with 12 cm, and the payload feels it (the descent's peak at the "
    "same 1.26 Hz, 0.11 m/s), where the 18-cell level breathes at 1.19 "
    "Hz with 1.6 cm: the frequency holds from 18 to 27 cells, the "
    "amplitude does not. Against the undamped tutorial's 27-cell level "
    "(7ft-cpd27-markerhalf-40s, study resolution7ftMarkerHalf: 0.872, "
    "5.47 ± 0.03 m/s) the damped one has 2.5 % more drag, about the "
    "pair's combined 95 % interval (±2.5 % in C_D0), and needs half the "
    "coupling iterations (1.17 against 2.23 a step). The 27-cell level "
    "(536 844 cells) ran in five parts, each continued from the latest "
    "write (`bin/canopy-validate run --continue`), 212 minutes of wall "
    "time on 2 ranks from rest to 40 s (0.18 simulated seconds a minute "
    "alone). The 7 ft summaries compared with this study (report.py, "
    "convergedStudy), against which the main job's 0.843, read over "
    "30-70 s, was 5.7 % low, until study levels7ftDamped read all three "
    "levels over 40-80 s: there the 27-cell level gives 0.859 and the "
    "main job is 1.9 % below it (4.3 % below the 27-cell level read over "
    "the main job's own 30-70 s).", ""]

# The tutorial as it is at 12 and 18 cells from rest to 80 s, read over
# 40-80 s (study levels7ftDamped)
LEVELS_DAMPED_PROSE = [
    "Each level from rest to 80 s in one piece, written every 0.5 s. At "
    "12 cells over 40-80 s: 5.53 ± 0.05 m/s, C_D0 0.851, Dp/D0 0.801 (the "
    "same set-up continued from a 40 s write, written every 0.25 s, gave "
    "0.835: runs whose writes differ part, as study default7ft found); "
    "read over the main job's 30-70 s, 0.843. At 18 "
    "cells over 40-80 s: 5.39 ± 0.07 m/s, C_D0 0.898, Dp/D0 0.807, crown "
    "0.243 against 0.220 D0, breathing at 1.22 Hz (St 0.39) with 1.5 cm "
    "against 0.55 Hz (St 0.17) with 5.5 cm. Over 10-40 s this 18-cell "
    "run gives 0.838, as 7ft-cpd18-markerhalf-loss0.02-40s did (0.839), "
    "but its descent goes on slowing after 40 s (5-s means 5.25-5.52 "
    "m/s over 40-80 s against 5.44-5.60 over 15-40 s): the damped 18-cell "
    "canopy, like the damped 12-cell one over 10-40 s, had not settled, "
    "and the closeness of the damped levels read over different windows "
    "(0.835 and 0.839, study damping7ftTutorial) does not hold over the "
    "same one. Over 40-80 s the levels differ by 5.5 %, beyond the "
    "pair's ±3.2 %, as the undamped levels do (0.852 at 12 cells over "
    "40-80 s, 0.910 at 18 over 10-40 s): the damping moves neither level "
    "beyond its window's uncertainty, and Roache's two-level bound at 18 "
    "cells (below) is ±31 %. The 12-cell level reads 1.37 coupling "
    "iterations a step over its window and takes 15.9 minutes to 80 s, "
    "the 18-cell level 1.20 and 61 minutes, on 2 ranks alone.", "",
    "**The third level**, 27 cells (7ft-cpd27-markerhalf-loss0.02-80s), "
    "goes on from the 40 s write of study resolution7ftDamped's 27-cell "
    "level (the same definition, written every 0.25 s) to 80 s. It ran "
    "in eleven parts, each continued from the latest write "
    "(`bin/canopy-validate run --continue`), 437 minutes of wall time "
    "for the 40 s on 2 ranks, much of it beside other runs (0.16-0.22 "
    "simulated seconds a minute alone). Over 40-80 s: 5.51 ± 0.10 m/s, "
    "C_D0 0.859, Dp/D0 0.812, silhouette 0.747 D0, crown 0.251 D0 above "
    "the skirt, breathing at 1.16 Hz (St 0.36) with 4.3 cm, felt by the "
    "payload at the same 1.16 Hz (0.04 m/s), 1.31 coupling iterations a "
    "step. Its descent wanders: the 5-s means run 5.44, 5.51, 5.47, "
    "5.32, 5.47, 5.59, 5.66 and 5.62 m/s (drift +0.24 m/s), so the "
    "window's interval is wider than the finer cells would suggest "
    "(±3.8 % in C_D0 against ±2.6 % at 18 cells and ±1.8 % at 12). The "
    "same level read over 10-40 s gave 0.894: the 27-cell canopy too "
    "moves by 4 % between windows.", "",
    "**The three levels over 40-80 s** give C_D0 0.851, 0.898 and 0.859 "
    "at 12, 18 and 27 cells: oscillatory, so Roache's GCI is the bound "
    "with safety factor 3 and the forcing's formal first order, C_D0 "
    "0.859 ± 27.4 % and the descent 5.51 m/s ± 13.3 % (the table above). "
    "That bound is the 18- and 27-cell levels' difference, 4.5 % of C_D0, "
    "and that difference lies inside their combined 95 % interval "
    "(±4.6 %): at this window's length the levels from 12 to 27 cells "
    "cannot be told apart except 12 from 18 (5.5 % against ±3.2 %). The "
    "shape converges: Dp/D0 0.801, 0.807 and 0.812, monotone at observed "
    "order 0.95, 0.812 ± 1.4 %; the silhouette 0.744, 0.758 and 0.747 "
    "D0; the crown 0.220, 0.243 and 0.251 D0 above the skirt. The "
    "breathing's frequency holds from 18 to 27 cells (1.22 and 1.16 Hz, "
    "St 0.39 and 0.36), its amplitude does not (1.5 and 4.3 cm); the "
    "12-cell level breathes in another mode (0.55 Hz). Since this study "
    "is complete the 7 ft summaries compare with it (report.py, "
    "convergedStudy): the main job, read over 30-70 s, gives 0.843, "
    "1.9 % below the 27-cell level's 0.859; the main job's set-up read "
    "over the same 40-80 s gives 0.851, 0.9 % below, and the 27-cell "
    "level read over the main job's 30-70 s gives 0.882, the main job "
    "4.3 % below it (docs/performance.md): inside issue 31's 5 % either "
    "way, "
    "with the GCI's bound of ±27 % beside it. Against Knacke's "
    "0.75-0.80 for solid flat circular canopies (NWC TP 6575, Table 5-1) "
    "the 27-cell level stands 7 % above the range's top. A 40-cell level "
    "(7ft-cpd40-narrow-damped-40s, the finest box 1.6 D0 wide, 0.86 M "
    "cells, about 9 hours on 2 ranks to 40 s) is defined and not yet "
    "run; read over a window no longer than 40 s, it would narrow the "
    "bound only if the window's scatter allows.", ""]

# What sets the 7 ft canopy's inflated shape: the cloth's stress by ring,
# the skirt's scallops between the lines, and 32 gores against 16 (study
# gores7ft; issue 34 item 1)
GORES_PROSE = [
    "**The cloth's stress and the skirt** (python/canopyfoam/"
    "cloth_stress.py, `python3 -m canopyfoam.cloth_stress "
    "build/validation/<run> T0 T1` from python/: the membrane stress by "
    "ring from the springs' tensions, meridional σ_mm and hoop σ_hh in "
    "N/m, and the skirt's radius at the lines and between them). The "
    "summaries' Dp/D0 is canopy.dat's projected diameter, twice the "
    "cloth's largest radius about the axis; the silhouette's diameter "
    "(the table above) is that of the circle of the area the cloth covers "
    "seen along the axis. On the tutorial's 16 gores the largest radius "
    "lies on the hem midway between two lines (as the radial tapes' "
    "section found over 8-12 s on an earlier set-up). At 12 and 18 cells "
    "over "
    "40-80 s (7ft-cpd12-damped-80s, 7ft-cpd18-damped-80s) and at 27 over "
    "20-40 s (7ft-cpd27-markerhalf-loss0.02-40s) the lines are attached "
    "at 0.701, 0.709 and 0.690 R0 and the hem between them reaches 0.805, "
    "0.811 and 0.812 R0; a taut hem, its rest length a gore (2π R0/16), "
    "arcing outward between the attachments reaches 0.805, 0.812 and "
    "0.796 R0. The hem is taut: the outer ring carries 4.3-6.6 N/m in hoop "
    "against 9.6-10.7 N/m meridional. Inwards the cloth is biaxial at the "
    "crown (σ_hh 15-21 N/m against σ_mm 16-36 within s < 0.2) and "
    "beyond carries 5-75 % of its meridional stress in hoop (ring means), "
    "so r σ_mm grows from 2-4 N at the crown to 7.7-8.5 N at the skirt. "
    "Tension-field "
    "theory (tension_field_shape.py, lines of 1 D0, section \"The cloth's "
    "stiffness in compression\") has no hoop stress and r σ_mm constant, "
    "and puts the attachments at 0.657 R0, 5-8 % inside the runs'.", "",
    "**The pressure jump from crown to skirt** (the same tool's last two "
    "columns: each ring's area-weighted mean of the jump the solver hands "
    "the cloth, canopy.h5's dp, and its ratio to the cloth's mean). "
    "Tension-field theory takes it uniform. On the same runs and windows "
    "it is uniform from the crown to s ≈ 0.65: 25.4-25.9, 24.3-24.6 and "
    "25.3-27.2 Pa at 12, 18 and 27 cells, 1.39-1.41, 1.39-1.41 and "
    "1.47-1.58 dynamic pressures (½ ρ V² at the window's mean descent, "
    "5.53, 5.39 and 5.35 m/s). Then it falls to 7.2, 6.9 and 5.9 Pa (0.3 "
    "of the cloth's mean) at s = 0.76, 0.82 and 0.86, where the cloth "
    "runs nearly parallel to the axis at r = 0.69-0.72 R0 (the pillbox's "
    "side wall), and rises at the hem to 42.8, 25.1 and 25.5 Pa. A "
    "membrane's normal balance, Δp = σ_mm κ_m + σ_hh κ_h, lets a small "
    "jump and a small hoop stress hold a meridian that is nearly straight, "
    "so the side wall and the low jump go together; the runs do not show "
    "which causes which. The low band lies 1.5-1.9 cells from the hem at "
    "each level (0.26, 0.19 and 0.15 m of the cloth's rest radius): "
    "closer to the skirt's free edge than two widths of the roma3 "
    "kernel's reach (1.5 cells), so its markers share cells with the "
    "hem's, and part of the band may be the forcing's and not the air's; "
    "that it moves towards the hem as the cells shrink, keeping its depth, "
    "points the same way. "
    "The mean jump, 22.2, 21.0 and 21.5 Pa, is 0.85-0.88 of the "
    "crown's. On the 32-gore run (below, 10-40 s) the jump is uniform at "
    "27.1-28.2 Pa out to s = 0.83, with no low band, and 56 Pa in the "
    "outer ring: there the skirt is the widest section and the side wall "
    "is not formed.", "",
    "**32 gores** (7ft-cpd18-gores32-40s: `canopy.nAttachments 32`, "
    "`lines.number 32`, otherwise the 18-cell level of study "
    "resolution7ftDamped). Predicted before the run, for attachments "
    "where the 16 gores have them (0.698 R0 over 10-40 s) and a taut hem "
    "arcing between them: its tips at 0.753 R0 and its outline 0.739 D0 "
    "across, which at 16 gores lies 0.02-0.03 D0 outside the silhouette, "
    "so a silhouette near 0.71 D0. The run cannot test that: a ring's "
    "node count is a multiple of the gores, and at this fabric edge the "
    "builder gives the skirt 32 nodes (the 16-gore cloth has 48), so "
    "every skirt node is an attachment and the hem between two lines is "
    "one spring that cannot arc; the cloth is coarser too (324 triangles, "
    "mean edge 0.168 m, against 368 and 0.153 m). What it shows is the "
    "skirt without its scallops: over 10-40 s the attachments stand at "
    "0.738 R0, the largest radius is 0.747 R0 (Dp/D0 0.749 against "
    "0.798), the hem is slack (the outer two rings carry 0.03-0.04 N/m in "
    "hoop, 64-72 % of their triangles wrinkled, against 5.8-6.4 N/m with "
    "16 gores), and the silhouette holds at 0.740 D0 against 0.751. C_D0 "
    "0.824 against 0.839 (-1.8 %, inside the pair's ±3.0 % and ±4.7 %), "
    "the descent 5.71 against 5.57 m/s with the 16 more lines' 0.17 kg "
    "(3.0 % of the weight), still slowing (drift -0.44 m/s against "
    "-0.23), breathing at 1.44 Hz with 5.6 cm against 1.19 Hz with 1.6 "
    "cm; 39 minutes on 2 ranks against 23.", "",
    "**32 gores on a finer cloth** (7ft-cpd18-edge0.83-gores32-40s: the "
    "fabric's edge at 0.83 finest cells, `edgeLengthPerCell 0.83`, "
    "0.098 m; 996 triangles and 64 skirt nodes, two hem springs a gore, "
    "so the hem can arc). The prediction above fails: the canopy opens "
    "wider, not narrower. Over 10-40 s the lines attach at 0.784 R0 (0.738 "
    "on the coarser 32-gore cloth, 0.698 with 16 gores), the hem between "
    "them reaches 0.850 R0, 0.018 R0 beyond a taut arc of its rest length "
    "(0.832: the hem is stretched), and the silhouette is 0.806 D0 "
    "against 0.740 and 0.751 (the taut-arc outline 0.818). Dp/D0 0.848, "
    "the crown 0.203 D0 above the skirt, C_D0 0.864 (5.57 ± 0.04 m/s, "
    "drift -0.24 m/s), 3.0 % above the 16-gore run and 4.9 % above the "
    "coarser 32-gore one, inside the pairs' combined 95 % intervals "
    "(±3.4 % and ±4.9 %): the drag hardly moves where the shape does. "
    "It breathes at 1.16 Hz (St 0.38) with 18 cm, ten times the 16-gore "
    "run's 1.6 cm, and the coupling takes 1.85 iterations a step over the "
    "window (1.1 on the coarser cloths); 56 minutes on 2 ranks. The "
    "cloth carries more hoop stress at the crown (σ_hh 17-23 N/m within s "
    "< 0.3) and r σ_mm reaches 9.0-9.2 N over 0.4 < s < 0.75. The "
    "pressure jump falls smoothly from 25.2-25.7 Pa at the crown to "
    "18.7-19.3 Pa at 0.7 < s < 0.9 (no low band) and peaks at the hem, "
    "73 Pa (2.6 times the cloth's mean, 28.2 Pa). Two things changed "
    "together, the gores and the cloth's edge: the same cloth with 16 "
    "gores (7ft-cpd18-edge0.83-gores16-40s) separates them: over 10-40 s "
    "its lines attach at 0.715 R0, the hem reaches 0.813 R0 (taut arc "
    "0.816), the silhouette is 0.762 D0 and Dp/D0 0.813, the crown 0.235 "
    "D0 above the skirt; C_D0 0.878 (5.45 ± 0.10 m/s, drift -0.28 m/s), "
    "breathing at 1.08 Hz (St 0.35) with 2.0 cm, 1.14 coupling iterations "
    "a step, 35 minutes on 2 ranks. Against the 1.25 edge with 16 gores "
    "the finer cloth moves the silhouette by +1.6 % (0.751 to 0.762), the "
    "attachments by +0.02 R0 and C_D0 by +4.6 %, inside the pair's ±4.7 "
    "%: the 16-gore shape holds in the cloth's resolution. On the same "
    "fine cloth 32 gores against 16 carry the attachments out by 0.07 R0 "
    "(0.784 against 0.715), the silhouette by +5.8 % (0.806 against "
    "0.762) and the breathing's amplitude from 2 to 18 cm, and change "
    "C_D0 by -1.6 % (inside ±4.0 %). The gore count, not the cloth, opens "
    "the canopy: the hem stays taut (its hoop stress 6.5-7.3 N/m in the "
    "outer ring), so its rest length fixes the mouth's perimeter, and "
    "the more lines hold it, the less of that length the scallops between "
    "them take up and the wider the attachments' circle must stand. The "
    "load at the hem, 29 Pa with 16 gores and 73 Pa with 32, pushes it "
    "out; how much of that peak is the air's and how much the IB "
    "forcing's at the cloth's free edge is not yet known. A real hem "
    "gathers (the handbook's canopies close to 0.67-0.70 D0), where the "
    "model's stays taut.", "",
    "**What this shows.** The 16-gore canopy's Dp/D0 of 0.80-0.81 is the "
    "taut hem's scallops between its lines, not the cloth's opening: "
    "without them (32 one-edge gores) it reads 0.75. At the fabric edge "
    "of 1.25 finest cells the silhouette, 0.74-0.76 D0 at 12, 18 and 27 "
    "cells and 0.74 without the scallops, stands 6-13 % wider than the "
    "handbook's Dp/D0 of 0.67-0.70 for flat circular canopies (Knacke, "
    "Table 5-1); the 16-gore silhouette holds on a finer cloth (0.762), "
    "and 32 gores open it to 0.81 by holding the taut hem at more "
    "points. The model's "
    "canopy is wider than tension-field theory where the theory leaves "
    "out the crown's biaxial stress: near the apex the cloth is not "
    "gathered (r ≈ s R0) and, pressurized, carries hoop stress, which "
    "flattens the crown and carries the attachments out. The theory's "
    "uniform pressure jump holds from the crown to s ≈ 0.65 and not at "
    "the skirt.", ""]

# What the markers half a cell apart do to the T-10's mapped levels
# (study markersT10)
MARKERS_T10_PROSE = [
    "The T-10's mapped levels hold the cloth at 0.446 m, so with the "
    "markers a cell apart (the library's default) each triangle has one "
    "marker and the markers lie 0.54 cells apart at 13 cells across D0 "
    "(0.82 m cells), 0.83 at 20 and 1.25 at 30. Over 2-12 s, at 13 cells "
    "the markers half a cell apart give C_D0 0.822 against 0.828 (-0.7 %, "
    "inside the pair's ±0.8 %): there the cloth's own markers were already "
    "closer than half a cell. At 20 cells they give 0.694 against 0.732 "
    "(-5.2 %, beyond ±2.0 %), the canopy opening wider (Dp/D0 0.773 "
    "against 0.745) and breathing 8.2 cm at 0.15 Hz against 2.2 cm at "
    "0.32 Hz, at 2.43 coupling iterations a step against 1.14 and still "
    "drifting (-0.17 m/s over the window). So the T-10, like the 7 ft "
    "canopy, is not converged in its markers while they are more than "
    "about half a cell apart. The 30-cell level with the markers half a "
    "cell apart (T10-mapped-cpd30-markerhalf, about 40 minutes on 2 "
    "ranks) stands stopped at its latest write, to be continued. "
    "T10-mapped-cpd13 and T10-mapped-cpd20 were re-made with the current "
    "code for this comparison: C_D0 0.828 and 0.732 where their earlier "
    "records (code bff5525) gave 0.832 and 0.743.", ""]

# What the hinge dashpots do to the T-10's mapped levels (study
# dashpotsT10)
DASHPOTS_T10_PROSE = [
    "From the inflated state the T-10's cloth holds without the hinge "
    "dashpots over the 12 s of each level (no step failed; 1.16 and 1.02 "
    "coupling iterations a step at 13 and 20 cells). Over 2-12 s they "
    "change C_D0 by -1.1 % at 13 cells (0.819 against 0.828, at the "
    "pair's ±1.1 %) and by -0.7 % at 20 (0.727 against 0.732, inside "
    "±1.4 %), and Dp/D0 by at most 0.008; what they hold down is the "
    "breathing, 3.7 cm against 1.0 cm at 13 cells and 9.5 cm against 2.2 "
    "cm at 20, at the same frequency (0.27 and 0.31 Hz against 0.25 and "
    "0.32). As on the 7 ft canopy (fabric.bendingDampingUntil, study "
    "resolution7ftUntil2), the dashpots set the breathing, not the drag, "
    "once the canopy is open; the tutorial keeps them throughout until "
    "a run from rest with them off after the inflation shows the "
    "inflation and the descent hold.", ""]

# What the T-10's cloths do with their markers half a cell apart on the
# 7 ft tutorial's coupling (studies markersT10Kernel and
# resolutionT10KernelMarkerHalf)
MARKERS_T10_KERNEL_PROSE = [
    "On the 7 ft tutorial's coupling (the load taken from the cells, the "
    "stabiliser's balance seen through the IB kernel) the T-10 "
    "tutorial's own cloth (1.03 m, 1.25 cells at 13 cells across D0) "
    "holds with its markers half a cell apart, where on its own coupling "
    "(each marker's own force) it closed and ran away at 47.9 s: from "
    "rest to 80 s in 3.3 minutes on 2 ranks at 1.22 coupling iterations "
    "a step (at most 6), over 50-80 s it descends at 6.37 ± 0.11 m/s, "
    "C_D0 0.755, Dp/D0 0.797, against the tutorial's 6.74 ± 0.21 m/s, "
    "0.675 and 0.768: +12 % in C_D0, beyond the pair's combined ±7.0 %. "
    "Taken from the cells, each marker's force is spread over the cells "
    "it forces before it loads the cloth, so four markers on a triangle "
    "no longer load it with patterns finer than the cloth. The T-10 "
    "tutorial runs on this coupling with its markers half a cell apart "
    "since the 30-cell level of study resolutionT10KernelMarkerHalf.",
    ""]
RESOLUTION_T10_KERNEL_MARKER_HALF_PROSE = [
    "With the markers half a cell apart on the 7 ft tutorial's coupling "
    "the mapped levels give C_D0 0.803, 0.722 and 0.719 at 13, 20 and 30 "
    "cells across D0 (6.18 ± 0.11, 6.52 ± 0.07 and 6.53 ± 0.14 m/s, "
    "Dp/D0 0.775, 0.765 and 0.762), against 0.8125, 0.7484 and 0.7066 "
    "with the markers a cell apart (study resolutionT10Kernel): -1.1 %, "
    "-3.5 % and +1.7 %, at 1.19 coupling iterations a step at every level "
    "(at most 11), where on each marker's own force half a cell moved the "
    "20-cell level by -5.2 % and doubled its iterations (study "
    "markersT10). The levels converge monotonically, the 20- and 30-cell "
    "levels 0.5 % apart (inside the pair's combined ±4.9 %): Roache's GCI "
    "of the 30-cell level (the table above) gives C_D0 0.719 ± 2.8 %, the "
    "descent 6.53 m/s ± 1.4 %, Dp/D0 0.762 ± 0.3 % (the observed order, "
    "about 7, lies outside [0.5, 3], so the estimate takes the safety "
    "factor 3 with the formal first order). Each level still slows across "
    "its window (drifts -0.32, -0.20 and -0.42 m/s over 2-12 s, the first "
    "10 s after the mapping), as the levels with the markers a cell apart "
    "do: the bound is the mesh's over this window, not the steady "
    "descent's. The 30-cell level took 17 minutes on 2 ranks. Against the "
    "T-10's published 6.7 m/s at 163 kg (C_D0 0.66, Mills Manufacturing) "
    "the 30-cell level is 2.5 % slower (C_D0 +9 %). The tutorial's 1.03 m "
    "cloth from rest on this coupling (T10-skirt-cpd13-m163-kernel-"
    "markerhalf, study markersT10Kernel) gives C_D0 0.755 over 50-80 s, "
    "5.0 % above it, and 0.814 over 80-120 s, 13 % above it (study "
    "payloadT10Tutorial: its descent wanders with a period of 20-30 s); "
    "the tutorial's earlier coupling (each marker's own force, its "
    "markers a cell apart) gives 0.675, 6.1 % below it, and 0.7 % from its own "
    "levels' 0.680 ± 13.2 % (study resolutionT10Mapped). On this "
    "coupling the payload sweep keeps C_D0 within 3 % from 100 to 300 kg "
    "in fewer coupling iterations (study payloadT10KernelMarkerHalf). "
    "The T-10 tutorial runs on this coupling since: studies "
    "payloadT10Tutorial and freeT10Tutorial.", ""]

# What the payload does on the 7 ft tutorial's coupling with the markers
# half a cell apart (study payloadT10KernelMarkerHalf)
PAYLOAD_T10_KERNEL_MARKER_HALF_PROSE = [
    "The T-10 tutorial's cloth on the 7 ft tutorial's coupling with its "
    "markers half a cell apart, each payload to 80 s and read over 50-80 "
    "s: C_D0 0.775, 0.755, 0.799 and 0.913 at 100, 163, 300 and 600 kg "
    "(4.98 ± 0.13, 6.37 ± 0.11, 8.34 ± 0.26 and 10.98 ± 0.28 m/s; Dp/D0 "
    "0.80-0.81), at 1.08, 1.22, 1.80 and 2.21 coupling iterations a step "
    "(2.7-8.6 minutes on 2 ranks), against 0.584, 0.675 (re-made), 0.736 "
    "and 0.745 on the tutorial's coupling with the markers a cell apart "
    "(study payloadT10SkirtLong, 2.45-3.95 iterations a step, 5.2-16.7 "
    "minutes). From 100 to 300 kg C_D0 stays within 3 % of 0.78, where on "
    "the tutorial's coupling it grows by 26 %; at 600 kg it rises 14 % "
    "above the 300 kg value. The fit V ∝ M^n gives n = 0.45 (0.43 on the "
    "tutorial's coupling). The 300 and 600 kg runs still slow across "
    "their window (drifts -0.62 and -0.53 m/s over 50-80 s), so their "
    "C_D0 is a lower bound of the steady value's; the 100 kg run still "
    "speeds up (+0.32 m/s). The same runs to 120 s, on the tutorial as it "
    "is now: study payloadT10Tutorial. Against the published 6.7 m/s at 163 kg (C_D0 "
    "0.66, Mills Manufacturing) the 163 kg run is 5 % slow, and against "
    "this coupling's converged 0.719 ± 2.8 % (study "
    "resolutionT10KernelMarkerHalf) its cloth at 13 cells is 5.0 % high.",
    ""]

# What the markers half a cell apart do to the T-10 tutorial's cloths
# (study markersT10Tutorial)
MARKERS_T10_TUTORIAL_PROSE = [
    "At 13 cells across D0 from rest to 80 s, on the T-10 tutorial's "
    "coupling (each marker's own force as the cloth's load, the "
    "stabiliser's balance of each triangle's plain mean): the tutorial's "
    "cloth (1.03 m edge, 1.25 finest cells) with its markers half a cell "
    "apart does not hold. It opens to 8.7-8.9 m across by 15 s (8.4-8.5 "
    "m with its markers a cell apart), then closes from 20 s (projected "
    "diameter "
    "6.7-7.1 m, 0.63-0.66 D0, over 25-50 s) while the descent rises to "
    "8.8 m/s and the coupling takes 4.5-8 iterations a step; at 47.87 s "
    "a cloth node passed the structure's speed limit (100 m/s) and the "
    "run stopped with its last good state written. The same cloth with "
    "its markers a cell apart, re-made with the current code, descends "
    "at 6.74 ± 0.21 m/s over 50-80 s (C_D0 0.675, Dp/D0 0.768). The 0.83 "
    "edge (0.683 m) holds with its markers half a cell apart: C_D0 0.809 "
    "against 0.815 (-0.7 %, its run as first made, code 11b7e31), opening "
    "wider (Dp/D0 0.790 against 0.755) and still speeding up over the "
    "window (+0.27 m/s). Four markers on a triangle that each carries "
    "its own force give the load patterns finer than the cloth, which "
    "the 7 ft tutorial's load from the cells (coupling.load.reaction "
    "cells) keeps off the cloth; the T-10 tutorial took its markers half "
    "a cell apart together with that coupling (study markersT10Kernel).",
    ""]

# The T-10 tutorial as it is, on the guide wire to 120 s (study
# payloadT10Tutorial) and in free flight (study freeT10Tutorial)
PAYLOAD_T10_TUTORIAL_PROSE = [
    "The T-10 tutorial as it is (the 7 ft tutorial's coupling, the "
    "markers half a cell apart), each payload from rest to 120 s and read "
    "over 80-120 s: C_D0 0.780, 0.814, 0.826 and 1.036 at 100, 163, 300 "
    "and 600 kg (4.96 ± 0.02, 6.14 ± 0.07, 8.20 ± 0.12 and 10.31 ± 0.40 "
    "m/s; Dp/D0 0.80 at each), at 1.06, 1.23, 2.02 and 2.31 coupling "
    "iterations a step (3.4, 4.4, 9.2 and 13.1 minutes on 2 ranks). The "
    "same runs read over 50-80 s gave 0.775, 0.755, 0.799 and 0.913 "
    "(study payloadT10KernelMarkerHalf): the 100 kg run has settled "
    "(drift -0.03 m/s over 80-120 s), the others wander with periods of "
    "20-30 s (163 kg between 5.94 and 6.50 m/s in 5-s means over 40-120 "
    "s, 300 kg between 8.04 and 8.65, 600 kg between 9.55 and 11.41), so "
    "a 30-40 s window holds one or two of those periods and their C_D0 "
    "moves by 3-14 % between windows; the 600 kg run's drift over its "
    "window (+1.17 m/s) is that wander. From 100 to 300 kg C_D0 stays "
    "within 6 %; the fit V ∝ M^n gives n = 0.42 where a constant C_D0 "
    "gives 1/2, the 600 kg point setting it. Against the published 6.7 "
    "m/s at 163 kg (C_D0 0.66, Mills Manufacturing) the 163 kg run is 8 % "
    "slow, and against the converged 0.719 ± 2.8 % of its coupling's "
    "mapped levels (study resolutionT10KernelMarkerHalf, read 2-12 s "
    "after the mapping) its C_D0 is 13 % high: the tutorial's 1.03 m "
    "cloth at 13 cells, read later in the descent.",
    "",
    "Breathing (issue 34 item 4; the table above, the projected "
    "diameter's and the descent speed's spectra over 80-120 s from St "
    "0.1): no T-10 run breathes near the seed's period of 2.3 s (0.43 "
    "Hz, St ≈ 0.5). At 100, 163 and 300 kg both spectra peak at the "
    "slow wander, 0.07-0.16 Hz (St 0.12-0.17, 3-7 periods in the window: "
    "not a breathing the window resolves), with the diameter moving by "
    "1-2 cm and the descent by 0.03-0.07 m/s; at 600 kg the diameter's "
    "peak is 0.36 Hz (St 0.30, 3.4 cm, 14 periods), the descent's still "
    "the wander's 0.16 Hz. Read at 13 cells across D0 only.", ""]
FREE_T10_TUTORIAL_PROSE = [
    "In free flight on the tutorial's coupling the T-10 holds its "
    "vertical descent much longer than on the earlier one. Its default "
    "(100 kg to 20 s, 45 s on 2 ranks, 1.26 coupling iterations a step) "
    "stays on the axis (the suspension within 0.001° of the vertical) and "
    "descends at 5.14 ± 0.08 m/s over 13.3-20 s, C_D0 0.726, Dp/D0 0.80, "
    "where on the earlier coupling it left the axis from about 13 s "
    "(T10-skirt-cpd13-default). At 163 kg to 60 s (3.1 minutes) the "
    "payload's sideways speed stays below 0.05 m/s to 35 s while the "
    "descent levels at 6.84-6.87 m/s (5-s means over 20-35 s, C_D0 0.63); "
    "then it grows as exp(σ t) with σ = 0.54 /s (σ D0/V = 0.84; doubling "
    "in 1.3 s), the suspension passes 5° at 45.3 s and its angle peaks "
    "at 2.9°, 8.5°, 29.9° and 48.0° at 42.3, 46.9, 56.2 and 59.5 s "
    "without returning to the vertical between (troughs 1.4-17.7°): a "
    "growing coning more than a swing through the vertical, too short "
    "for a period (the table's 13 s spans one of them). On the earlier coupling the same "
    "flight departed from about 10 s with σ = 0.96 /s and tumbled by 32.5 "
    "s (T10-free-cpd13-m163). The departure is delayed, not removed: "
    "against the ±10-15° published for extended-skirt canopies (Knacke, "
    "NWC TP 6575, Table 5-1) it stays a finding. From 20 s the free "
    "flight descends faster than the same canopy on the guide wire "
    "(6.84-6.96 against 6.08-6.68 m/s in 5-s means over 20-40 s) with "
    "the payload still on the axis; the wire holds the apex over the "
    "payload, so the canopy cannot tilt as the wake's symmetry breaks "
    "(a likely cause, not measured).", ""]

# What the T-10 tutorial's hinge dashpots do in steady descent (study
# dashpotsT10Tutorial, issue 34 item 2)
DASHPOTS_T10_TUTORIAL_PROSE = [
    "The T-10 tutorial keeps its hinge dashpots (10 000 /s) throughout. "
    "Off from 10 s (fabric.bendingDampingUntil 10, about 5 D0/V, as the "
    "7 ft tutorial's 2 s) the cloth holds from rest to 120 s on the guide "
    "wire, and over 80-120 s the descent is 6.19 ± 0.14 m/s against 6.14 "
    "± 0.07 (C_D0 0.802 against 0.814, -1.5 %, inside the pair's "
    "combined interval and the resolution study's ±2.8 %), Dp/D0 0.797 "
    "against 0.798, the crown 2.82 m above the hem and the largest radius "
    "4.25 m in both (0.3 %), the projected diameter's standard deviation "
    "3.4 cm against 3.7 cm: neither run breathes at the seed's 2.3 s "
    "(the undamped run's projected diameter peaks at 0.07 Hz with 2.6 "
    "cm, the period of the descent's wander), at 1.32 against 1.23 coupling iterations a step. On this "
    "coupling the dashpots change neither the descent nor the shape nor "
    "the breathing beyond their uncertainty in steady descent (the "
    "mapped levels' dashpotsT10 found the same on the earlier coupling); "
    "their effect on the free flight's departure: study dashpotsT10Free.",
    ""]

# ... and in free flight (study dashpotsT10Free)
DASHPOTS_T10_FREE_PROSE = [
    "In free flight at 163 kg the T-10 departs from the vertical with or "
    "without its hinge dashpots: off from 10 s the payload's sideways "
    "speed grows from about 35 s as exp(σ t) with σ = 0.45 /s (σ D0/V = "
    "0.73) against 0.54 /s (0.81) with them, the suspension passes 5° at "
    "50.3 s against 45.3 s and reaches 37.6° against 48.1° by 60 s (rms "
    "7.9° against 11.7° over 15-60 s). The dashpots neither cause the "
    "departure nor hold it off; the two runs part where a growing "
    "instability makes the timing sensitive to any change. Over 15-60 s, "
    "swing included, the undamped run gives C_D0 0.720 against 0.690.",
    ""]

# The C-9 on the T-10 tutorial's coupling (study couplingC9, issue 34
# item 6)
COUPLING_C9_PROSE = [
    "On the T-10 tutorial's coupling (the load taken from the cells, the "
    "stabiliser's balance seen through the IB kernel from zero each step, "
    "the markers half a cell apart, Aitken's factor from 1) the C-9 at "
    "100 kg on the guide wire, 13 cells across D0, takes 1.11 coupling "
    "iterations a step (at most 8) against 4.45 (at most 32) on its "
    "tutorial's coupling, and over 60-120 s descends at 5.45 ± 0.12 m/s "
    "against 5.60 ± 0.07: C_D0 1.007 against 0.954 (+5.6 %, just beyond "
    "the pair's combined ±5.2 % in C_D0), Dp/D0 0.87 in "
    "both, its crown 1.79 m above the hem against 2.09 m (a flatter "
    "dome). It still slows across the window (drift -0.39 m/s, 5-s means "
    "5.26-5.67 m/s), where the tutorial's run has settled (-0.01). Both "
    "lie well above the handbook's 0.75-0.80 for flat circular canopies "
    "(Knacke, NWC TP 6575, Table 5-1). One level on each coupling: which "
    "is nearer the converged value needs the C-9's resolution study, so "
    "the C-9 tutorial keeps its coupling.", ""]

# Whether a level between 12 and 18 cells serves the main job better
# (study mainJobLevel7ft, issue 31 §4)
MAIN_JOB_LEVEL_PROSE = [
    "Issue 31 §4 asks for the cheapest setting within 5 % of the "
    "converged C_D0 (0.872 ± 26.1 %, study resolution7ftMarkerHalf) that "
    "finishes in 15 minutes on 2 cores. 12 cells (the main job) give "
    "0.828 in 9.1 minutes, 5.05 % low; 13 cells give 0.811 (5.67 ± 0.16 "
    "m/s, Dp/D0 0.803, breathing 1.05 Hz with 8 cm) in 12.1 minutes, 7.0 "
    "% low, and still slow across the window (drift -0.34 m/s over 10-40 "
    "s against -0.09 at 12 cells). Both lie inside the converged value's "
    "GCI, and the levels oscillate (0.828, 0.811, 0.910, 0.872 at 12, "
    "13, 18 and 27 cells), so a level's error is not monotone in its "
    "cost. From the two runs' cost (time ∝ N^3.6 for N cells across D0) "
    "14 cells would take about 15.5 minutes, over the limit: the main job "
    "keeps 12 cells and its summary states its error.", ""]

TURBULENCE_CONVERGED_PROSE = [
    "The LES run took each marker's own force as the load "
    "(coupling.load.reaction markers), the tutorial's load when it ran. Its "
    "laminar partner is the main job's 40 s run of that time "
    "(7ft-default-markers-40s: the record of 7ft-default-40s as run at "
    "70b31d1, kept under its own name since 7ft-default-40s was run again "
    "on the load taken from the cells). Paired with the re-run "
    "7ft-default-40s, this section read the load's change (C_D0 0.674 "
    "against 0.874) as LES's. Study turbulence7ftDamped compares LES with "
    "laminar on the tutorial as it is.", ""]


TURBULENCE_DAMPED_PROSE = [
    "Each pair from rest, read over the same window. At 12 cells across D0 "
    "(the main job's set-up, 30-70 s) LES gives 5.568 ± 0.046 m/s, C_D0 "
    "0.841 against the laminar 5.559 ± 0.068 and 0.843 (-0.3 %); at 18 "
    "cells (40-80 s) 5.382 ± 0.045 m/s, C_D0 0.900 against 5.387 ± 0.068 "
    "and 0.898 (+0.2 %). Both changes lie inside the pairs' combined "
    "intervals (about ±3 %) and far inside the converged value's GCI, and "
    "the 12-to-18-cell change of C_D0 is the same with and without LES "
    "(+6.5 % and +7.1 %, 30-70 s at 12 cells against 40-80 s at 18). "
    "Dp/D0 is 0.786 against 0.800 at 12 cells and 0.808 against 0.807 at "
    "18; the crown stands 0.229 "
    "against 0.220 D0 and 0.238 against 0.243 D0 above the skirt; the "
    "breathing's largest peak is 0.44 against 0.56 Hz (3.9 against 4.7 cm) "
    "at 12 cells and 1.24 against 1.22 Hz (2.2 against 1.5 cm) at 18. The "
    "WALE eddy viscosity reaches 0.08 m²/s (5 500 times air's) next to the "
    "canopy in the 12-cell run's last state, yet the descent, the shape "
    "and the breathing move less than the windows' scatter, as expected "
    "of a bluff body whose flow separates at a sharp edge (the skirt), "
    "where the separation does not depend on the boundary layer the "
    "sub-grid model would change. LES costs 964 against 829 s at 12 "
    "cells (+16 %) and 94 against 61 minutes at 18 (+53 %, its coupling "
    "taking 1.78 "
    "iterations a step against 1.20). The tutorials stay laminar.", ""]


DISC_TUTORIAL_PROSE = [
    "The disc of study disc7ft (the 7 ft cloth's flat disc, D0 = 2.134 m, "
    "its nodes fixed, impermeable, in a 5 m/s stream: Re = 7e5) on the "
    "forcing of the tutorial as it is, its markers half a cell apart, read "
    "over 5-20 s (35 D0/U). The force in the table is canopy.dat's, the "
    "resultant of the load the cloth is handed: for the three levels the "
    "IB force's reaction taken from the cells (the tutorial's load, equal "
    "and opposite to the force on the air); for "
    "disc-markerhalf-sampled-cpd18 the air's pressure read 3 cells off "
    "each side of the markers (clothLoads::sampled). The nodes are fixed, "
    "so the load does not act back on the air: the 18-cell pair is one "
    "flow (its velocity and pressure at 20 s are the same to the bit), "
    "read two ways.", "",
    "**The drag.** C_D 1.305, 1.300 and 1.391 at 12, 18 and 27 cells "
    "across D0, ± 0.13, ± 0.09 and ± 0.13 (the mean's 95 % interval from "
    "the series' autocorrelation): the laminar wake's recirculation grows "
    "and sheds slowly, and its 5-s means over 5-10, 10-15 and 15-20 s run "
    "1.26, 1.20, 1.45 (12 cells), 1.27, 1.24, 1.40 (18) and 1.28, 1.38, "
    "1.51 (27, still rising). Published for a disc above Re ~ 1e4 (study "
    "disc7ft's sources): 1.1-1.17. The forcing's drag lies 11-16 % above "
    "at 12 and 18 cells and 19-24 % above at 27: not converged (the "
    "levels oscillate, Roache's bound ± 39 %, below), the finest level "
    "giving the most, as with the markers a cell apart "
    "(study disc7ft, over 4-12 s: 1.235, 1.214 and 1.310). Inside the rim, "
    "where the forcing and the air agree (below), the jump at the centre "
    "rises with the mesh, 0.89, 1.00 and 1.21 q: the laminar wake of a "
    "symmetric start (no turbulence model at Re 7e5) holds a deeper base "
    "pressure as it is resolved. The air's pressure read 3 cells off the "
    "disc gives C_D 1.076 ± 0.07 on the 18-cell flow, 17 % below the "
    "forcing's: a sample 3 cells off misses the force that turns the air "
    "between it and the disc, and at the rim reads air beside it.", "",
    "**Where the load lies** (the table below; `python3 -m "
    "canopyfoam.cloth_stress build/validation/<run> 5 20 20` from "
    "python/ prints the same rings). Inside the rim the two agree: over "
    "s < 0.85 the IB force's reaction carries 43.9 N and the air's "
    "sampled pressure 44.5 N at 18 cells (1.4 % apart), ring by ring "
    "within -4 % to +7 %. In the outermost cell they part: the reaction "
    "rises to 1.65 and 2.43 q in the last two rings (s = 0.93 and 0.98, "
    "within 0.7 cells of the rim) where the sampled pressure falls to 1.07 "
    "and 1.05 q. On a real disc the front face's pressure is highest at "
    "the stagnation point and falls as the air speeds up towards the rim "
    "(Bernoulli), while the separated wake's is nearly uniform, so the "
    "jump has no peak at the rim: the peak is the forcing's, the rim "
    "markers' kernel reaching 1.5 cells beyond the disc and stopping air "
    "that passes outside it. It shrinks with the cell: the band s > 0.85 "
    "(31, 24 and 26 % of the disc's area at 12, 18 and 27 cells) carries "
    "50, 37 and 33 % of the drag, its mean jump 2.28, 1.92 and 1.39 times "
    "the interior's, an excess over the interior's level of 19.8, 12.5 "
    "and 6.8 N, 28, 18 and 9 % of the drag: about first order in the "
    "cell, while the last ring's peak stays at 2.3-2.6 q as the ring "
    "narrows. At 18 cells the whole difference between the reaction's and "
    "the sampled drag (12.0 N of 69.7) lies in that band (26.1 against "
    "13.5 N). This answers issue 34's question for a free edge held "
    "still: the hem's load peak on the canopy (studies gores7ft and "
    "levels7ftDamped: up to 2.6 times the cloth's mean at the hem) is of "
    "the same kind, a load the "
    "air's pressure does not carry, pushing the hem outward along its "
    "normal; on the disc it is a discretisation error of the forcing "
    "that falls about as the cell.", ""]


LOAD_SAMPLED_PROSE = [
    "The disc's finding tried on the canopy (study discTutorial7ft: the "
    "IB force's reaction carries a peak in the outermost cell of a free "
    "edge that the air's pressure does not): the 12-cell tutorial with "
    "the air's pressure sampled 3 cells off each side of the markers as "
    "the cloth's load (`coupling.load { type sampled; pressureHeld true; "
    "}`, no tangential part) instead of the reaction. The tutorial's load "
    "is the reference (7ft-cpd12-markerhalf-loss0.02-40s; from rest the "
    "same set-up, 7ft-cpd12-damped-70s, stands at 0.78-0.83 D0 from "
    "1.1 s).", "",
    "**It closes.** With the hinge dashpots off from 2 s (the tutorial's) "
    "the sampled load's canopy inflates to 0.66-0.70 D0 over 1.5-2.6 s, "
    "then closes to 0.53-0.54 D0 by 3.3-3.6 s; its drag falls from 56 to "
    "13 N, the descent speeds up to 11 m/s, and at 4.02 s the apex passes "
    "the structure's speed limit (100 m/s) in an HHT sub-step (the last "
    "good state is written). With the dashpots throughout it holds to "
    "about 8 s, then closes the same way (0.51 D0 at 8.7 s): over 3-7.5 "
    "s it stands at Dp/D0 0.667, silhouette 0.636 D0, the crown 0.288 D0 "
    "above the skirt, and descends at 6.96 m/s, still speeding up (+0.56 "
    "m/s over the interval): C_D0 0.537, against the reference's 0.768 "
    "and the handbook's 0.75-0.80. The sample misses the force "
    "that turns the air between it and the cloth (on the disc 17 % of "
    "the drag), and at 12 cells the 3 cells are 0.25 D0, so the skirt's "
    "samples read the air outside the mouth: not a load to run the "
    "tutorial on.", "",
    "**But its shape is tension-field theory's.** Read by ring over 3-7.5 "
    "s (`python3 -m canopyfoam.cloth_stress <run> 3 7.5`), the sampled "
    "jump is highest at mid-canopy (1.32 times the cloth's mean at s = "
    "0.4) and falls towards the skirt (0.82 and 0.66 in the last two "
    "rings), the hoop stress vanishes from s = 0.55 outwards (67-100 % of "
    "the triangles wrinkled) and r σ_mm holds at 7.6-8.7 N: the "
    "theory's assumptions. The lines attach at 0.585 R0, the hem reaches "
    "0.665 R0, the silhouette is 0.636 D0, against the theory's skirt at "
    "0.657 R0 and widest radius 0.676 R0. The tutorial's load over the "
    "same 3-7.5 s (7ft-cpd12-damped-70s) falls to 0.45 of its mean at s = "
    "0.76 and peaks at the hem (1.37 and 1.94 times the mean in the last "
    "two rings), whose hoop stress stays at 6.0 N/m: the lines attach at "
    "0.725 R0, the hem reaches 0.817 R0, the silhouette 0.768 D0. Two "
    "readings stay open. The reaction's peak at the free edge, which the "
    "air's pressure does not carry on the disc, pushes the hem out; but "
    "on the disc that peak's excess falls threefold from 12 to 27 cells "
    "while the canopy's Dp/D0 holds at 0.80-0.81 over those levels (study "
    "levels7ftDamped), so it does not alone set the mouth. And the "
    "sampled load reads the skirt's air 0.25 D0 away, under-loading the "
    "hem, which may be why that canopy narrows and then closes. Either "
    "way the canopy's drag on its own silhouette is about the same (1.33 "
    "sampled over 3-7.5 s, 1.37 with the reaction over 10-40 s), against "
    "the 1.5-1.8 the handbook's C_D0 and Dp/D0 imply together: the "
    "model's mouth, wider than the handbook's, makes up for too little "
    "drag per area, and its C_D0 comes near the handbook's through that "
    "compensation. A load that keeps the reaction (the air's whole force, "
    "its added mass included) without the forcing's excess at a free "
    "edge, measured first on the disc, is the open step.", ""]


TUTORIAL_STUDY_PROSE = {
    "mainJobLevel7ft": MAIN_JOB_LEVEL_PROSE,
    "payloadT10Tutorial": PAYLOAD_T10_TUTORIAL_PROSE,
    "dashpotsT10Tutorial": DASHPOTS_T10_TUTORIAL_PROSE,
    "couplingC9": COUPLING_C9_PROSE,
    "dashpotsT10Free": DASHPOTS_T10_FREE_PROSE,
    "freeT10Tutorial": FREE_T10_TUTORIAL_PROSE,
    "payloadT10KernelMarkerHalf": PAYLOAD_T10_KERNEL_MARKER_HALF_PROSE,
    "resolution7ftUndampedContinued": UNDAMPED_CONTINUED_PROSE,
    "resolution7ftUntil2": UNTIL_TWO_PROSE,
    "resolution7ftUntil2Long": UNTIL_TWO_LONG_PROSE,
    "window7ft12": WINDOW_12_PROSE,
    "coarse7ftTutorial": COARSE_TUTORIAL_PROSE,
    "domain7ftTutorial": DOMAIN_TUTORIAL_PROSE,
    "timeStep7ftTutorial": TIME_STEP_TUTORIAL_PROSE,
    "edgeLength7ftTutorial": EDGE_TUTORIAL_PROSE,
    "edgeLength7ftTutorialTo80": EDGE_TUTORIAL_80_PROSE,
    "markers7ftTutorial": MARKERS_TUTORIAL_PROSE,
    "resolution7ftMarkerHalf": MARKER_HALF_PROSE,
    "numerics7ftMarkerHalf": NUMERICS_MARKER_HALF_PROSE,
    "quasiNewtonReuse7ft": QN_REUSE_PROSE,
    "iterations7ft": ITERATIONS_7FT_PROSE,
    "damping7ftTutorial": DAMPING_7FT_TUTORIAL_PROSE,
    "resolution7ftDamped": RESOLUTION_DAMPED_PROSE,
    "levels7ftDamped": LEVELS_DAMPED_PROSE,
    "gores7ft": GORES_PROSE,
    "discTutorial7ft": DISC_TUTORIAL_PROSE,
    "load7ftSampled": LOAD_SAMPLED_PROSE,
    "markersT10": MARKERS_T10_PROSE,
    "dashpotsT10": DASHPOTS_T10_PROSE,
    "markersT10Tutorial": MARKERS_T10_TUTORIAL_PROSE,
    "markersT10Kernel": MARKERS_T10_KERNEL_PROSE,
}
