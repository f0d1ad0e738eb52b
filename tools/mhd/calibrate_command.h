#pragma once
// `mhd calibrate SAMPLES.csv --rig RIG.xml [-o OUT.xml]`: fits the rig's sensor -> PHANToM
// offsets and the yaw psi to measured samples (thesis ch. 4.4; engine/calibration), prints
// the residual RMSE per axis before and after, and writes the calibrated rig XML.
// `mhd calibrate --synthesize SAMPLES.csv --rig RIG.xml`: writes thesis-like samples from the
// rig with known offsets, psi and tracker noise instead. docs/calibration.md.
// Exit status: 0 done, 1 bad samples / rig / a refused fit (no file written), 2 usage.

#include <CLI/CLI.hpp>

void add_calibrate_command(CLI::App& app);
