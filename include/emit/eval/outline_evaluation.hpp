#pragma once
/// \file outline_evaluation.hpp
/// `emit eval --outlines`: how well each method images pressed regions of many outlines (issue
/// 31), on a flat sheet (the 60 mm one by default). On the twin, on a mesh of another seed than the
/// reconstruction's:
///
/// 1. a reference of no-press frames and calibration presses of a 5 mm flat disc at random places,
///    2–39 N (as `emit eval --realistic`'s round); each method calibrated on them as `emit
///    calibrate` would (pipeline/press_calibration.hpp, its defaults);
/// 2. frames of flat punches of the families of twin/outline_scripts.hpp (bars, an ellipse, a
///    ring, a palm-sized disc, an L, two parallel bars, a stylus tip) at random places and angles,
///    4–16 N;
/// 3. each frame reconstructed by each calibrated method (contact fitting cold, each frame on its
///    own), its pressed region (Reconstructor::pressure() > 0) scored against the outlines by
///    eval/outline_scoring.hpp, averaged per family.
///
/// Each family's reported area and force are also scored for coverage: the fraction of frames
/// whose true area (force) lies within the reported 1σ and 2σ (outline_scoring.hpp's
/// within_sigmas), for methods that report σ.
///
/// `--indenters` (OutlineEvalOptions::indenters): the same round with flat discs of radius 2, 3,
/// 5, 7 and 10 mm for families, after the same calibration with 5 mm discs; contact fitting's
/// methods then also with each disc's radius declared (FrameOptions::contact_radius_mm).
///
/// Lengths are the 60 mm sheet's: another sheet must have room for a 30 mm bar.
#include <cstdint>
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/outline_scoring.hpp"
#include "emit/eval/sheet_evaluation.hpp"
#include "emit/model/method.hpp"
#include "emit/twin/outline_scripts.hpp"

namespace emit {

struct OutlineEvalOptions {
  std::vector<Method> methods{Method::paper, Method::noser, Method::laplacian, Method::fit};
  int mesh_seed = 3;        ///< the twin's mesh (another than the reconstruction's)
  std::uint64_t seed = 21;  ///< the noise and the calibration presses; the outlines' from seed + 1 on
  int reference_frames = 10;
  int calibration_presses = 40;  ///< calibrate_sensor needs 8 or more
  int presses_per_family = 6;    ///< 48 frames of outlines in all
  /// Contact fitting's sensor calibration's most iterations (0: `emit calibrate`'s own).
  int calibration_iterations = 0;
  /// The indenter sweep instead of the outlines: flat discs of these radii, a family each.
  bool indenters = false;
  std::vector<double> indenter_radii_mm{2, 3, 5, 7, 10};
  void validate() const;  ///< \throw InvalidInput naming the option
};

/// Options for a smoke test (`--quick`): one frame of each family, 16 calibration presses, the
/// sensor fit stopped after 2 iterations (as quick_realistic_counts).
OutlineEvalOptions quick_outline_options();

/// Scores averaged over one family's frames (or all of them).
struct OutlineFamilyScore {
  std::string family;
  int frames = 0;
  double dice = 0;         ///< mean
  double force_error = 0;  ///< mean |F̂ − F| / F (a fraction)
  double force_ratio = 0;  ///< mean F̂ / F
  double centroid_mm = 0;  ///< mean over the frames with a region
  int frames_without_region = 0;
  double orientation_deg = 0;  ///< mean over elongated outlines' frames (NaN without any)
  double regions = 0;          ///< mean count reported
  double right_count = 0;      ///< fraction of frames reporting as many regions as presses
  double area_ratio = 0;       ///< mean Â/A, the contacts' total area against the outlines'
  /// Fractions of the frames whose true area (force) lies within the reported 1σ (2σ) (a frame
  /// without contacts counts as outside); NaN where no frame reported a σ of it.
  double area_within_1sigma = 0, area_within_2sigma = 0;
  double force_within_1sigma = 0, force_within_2sigma = 0;
};

struct MethodOutlineScore {
  Method method = Method::paper;
  bool declared_radius = false;              ///< each indenter's radius declared (--indenters)
  std::vector<OutlineFamilyScore> families;  ///< in outline_families()' (the radii's) order
  OutlineFamilyScore all;
  double calibration_rms_N_per_mm2 = 0;  ///< the calibration's own misfit on its presses
  double ms_per_frame = 0;
};

struct OutlineEvaluation {
  long triangles = 0;  ///< the reconstruction mesh's
  int calibration_presses = 0;
  bool indenters = false;  ///< the indenter sweep's families
  std::vector<MethodOutlineScore> methods;
};

/// Averages frame scores into a family's (name `family`).
OutlineFamilyScore summarize_outline_scores(const std::string& family, const std::vector<OutlineScore>& scores);

/// The round on `eval_case`'s (flat) sheet. \throw InvalidInput (bad options, a curved sheet, one
/// without room), SolverError.
OutlineEvaluation evaluate_outlines(const EvalCase& eval_case, const OutlineEvalOptions& options,
                                    const Progress& progress = {});

}  // namespace emit
