#pragma once
/// \file figures_of_merit.hpp
/// `emit eval --figures-of-merit`: GREIT's figures of merit (eval/greit_merit.hpp) as the EIT
/// field measures a method: small presses (a point-like target: r 3 mm, 8 N by default) at places
/// from the sheet's centre towards its border along a few rays, frames from the twin on a mesh of
/// its own (docs/physics.md, "The digital twin"), each method's image of each: a linear method's
/// δφ (Reconstructor::image(), eq. 7), contact fitting's pressure picture
/// (Reconstructor::pressure()); a linear method's pressure picture (eq. 8 above its threshold) too,
/// the picture a user sees. Per method, each figure's mean and spread over the places, AR's
/// coefficient of variation (GREIT asks AR to be uniform over the sheet), and a plot per figure
/// against the place's distance from the centre.
#include <cstdint>
#include <string>
#include <vector>

#include "emit/core/progress.hpp"
#include "emit/eval/greit_merit.hpp"
#include "emit/eval/sheet_evaluation.hpp"
#include "emit/model/method.hpp"

namespace emit {

struct FiguresOfMeritOptions {
  std::vector<Method> methods{Method::paper, Method::noser, Method::laplacian, Method::fit};
  double radius_mm = 3, force_N = 8;  ///< the presses: flat punches
  double step_mm = 3;                 ///< between places along a ray
  int rays = 3;                       ///< from the centre at 0°, 45°/(rays − 1) … 45° (one eighth of a square)
  double margin_mm = 1;               ///< the press's rim at least this far inside the border
  int mesh_seed = 3;                  ///< the twin's mesh (another than the reconstruction's)
  std::uint64_t seed = 1;             ///< the ADC's noise
  void validate() const;              ///< \throw InvalidInput naming the option (core/option_check.hpp)
};

/// One press's image, scored.
struct MeritSample {
  Vector2 target_mm{0, 0};
  double distance_from_centre_mm = 0;
  GreitMerit merit;
};

/// Mean and standard deviation (n − 1) over the places.
struct MeritSpread {
  double mean = 0, std = 0;
};

struct MethodMerit {
  Method method = Method::paper;
  /// Which picture was scored: the pressure picture (eq. 8 above the threshold for a linear
  /// method, Reconstructor::pressure()) or, for a linear method, its image δφ.
  bool pressure = false;
  std::vector<MeritSample> samples;  ///< the places whose image was not 0
  int blank = 0;                     ///< frames whose image was 0 everywhere (nothing found)
  /// AR in the image's unit × mm² per newton (δφ: V·mm²/N; pressure: N/N, 1 when calibrated).
  MeritSpread amplitude_response, position_error_mm, resolution, shape_deformation, ringing;
  double amplitude_response_cv = 0;  ///< std / |mean| of AR
};

struct FiguresOfMerit {
  std::vector<MethodMerit> methods;  ///< per method; a linear one twice, δφ then pressure
  int places = 0;
  long triangles = 0;  ///< the reconstruction mesh's
};

/// The places a press of `options` goes on `sensor`'s flat sheet: its centre of gravity, then every
/// step along each ray while the press's rim stays margin_mm inside the border.
/// \throw InvalidInput for a bad option or a curved sheet.
std::vector<Vector2> figure_of_merit_places(const Sensor& sensor, const FiguresOfMeritOptions& options);

/// \throw InvalidInput for a bad option or a curved sheet; SolverError.
FiguresOfMerit evaluate_figures_of_merit(const EvalCase& eval_case, const FiguresOfMeritOptions& options,
                                         const Progress& progress = {});

/// A PNG per figure against the distance from the centre, a series per method, into `dir`
/// (created), named after the case: `<case>_merit_<figure>.png`. AR is drawn over each method's
/// mean (their units differ). \return the paths. \throw IoError.
std::vector<std::string> write_figure_of_merit_plots(const EvalCase& eval_case, const FiguresOfMerit& merit,
                                                     const std::string& dir);

}  // namespace emit
