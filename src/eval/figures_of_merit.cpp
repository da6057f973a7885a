#include "emit/eval/figures_of_merit.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <utility>

#include "emit/core/errors.hpp"
#include "emit/core/option_check.hpp"
#include "emit/eval/evaluation.hpp"
#include "emit/eval/resolvability.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/render/image.hpp"
#include "emit/render/line_plot.hpp"
#include "emit/sensor/surface.hpp"

namespace emit {

namespace {

MeritSpread spread(const std::vector<double>& values) {
  MeritSpread s;
  if (values.empty()) return {NAN, NAN};
  for (double v : values) s.mean += v;
  s.mean /= static_cast<double>(values.size());
  for (double v : values) s.std += (v - s.mean) * (v - s.mean);
  s.std = values.size() > 1 ? std::sqrt(s.std / static_cast<double>(values.size() - 1)) : 0;
  return s;
}

void summarise(MethodMerit& m) {
  std::vector<double> ar, pe, res, sd, rng;
  for (const MeritSample& s : m.samples) {
    ar.push_back(s.merit.amplitude_response);
    pe.push_back(s.merit.position_error_mm);
    res.push_back(s.merit.resolution);
    sd.push_back(s.merit.shape_deformation);
    rng.push_back(s.merit.ringing);
  }
  m.amplitude_response = spread(ar), m.position_error_mm = spread(pe), m.resolution = spread(res);
  m.shape_deformation = spread(sd), m.ringing = spread(rng);
  m.amplitude_response_cv = m.amplitude_response.std / std::abs(m.amplitude_response.mean);
}

std::string file_stem(const std::string& name) {
  std::string stem;
  for (char ch : name)
    if (std::isalnum(static_cast<unsigned char>(ch)))
      stem += static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
    else if (!stem.empty() && stem.back() != '_') stem += '_';
  while (!stem.empty() && stem.back() == '_') stem.pop_back();
  return stem;
}

}  // namespace

void FiguresOfMeritOptions::validate() const {
  if (methods.empty()) option_check::fail("FiguresOfMeritOptions", "methods", "one method or more", "none");
  option_check::positive("FiguresOfMeritOptions", "radius_mm", radius_mm);
  option_check::positive("FiguresOfMeritOptions", "force_N", force_N);
  option_check::positive("FiguresOfMeritOptions", "step_mm", step_mm);
  option_check::at_least("FiguresOfMeritOptions", "rays", rays, 1);
  option_check::non_negative("FiguresOfMeritOptions", "margin_mm", margin_mm);
}

std::vector<Vector2> figure_of_merit_places(const Sensor& sensor, const FiguresOfMeritOptions& options) {
  options.validate();
  require_flat_sheet(sensor, "--figures-of-merit");
  const Border& border = sheet_outline(sensor);
  // The outline's centre of gravity, from a fine sampling of its bounding box (the mesh's would do
  // as well; this needs none).
  Vector2 low(INFINITY, INFINITY), high(-INFINITY, -INFINITY);
  for (int i = 0; i < 1000; ++i) {
    const Vector2 p = border.point_at(border.length_mm() * i / 1000.0);
    low = low.cwiseMin(p), high = high.cwiseMax(p);
  }
  Vector2 sum(0, 0);
  int inside = 0;
  const int n = 200;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const Vector2 p(low.x() + (high.x() - low.x()) * (i + 0.5) / n, low.y() + (high.y() - low.y()) * (j + 0.5) / n);
      if (border.contains(p)) sum += p, ++inside;
    }
  const Vector2 centre = sum / inside;
  const double clearance = options.radius_mm + options.margin_mm;
  const auto fits = [&](const Vector2& p) {
    return border.contains(p) && border.distance_to_border_mm(p) >= clearance;
  };
  if (!fits(centre)) throw InvalidInput("figures of merit: the press does not fit at the sheet's centre");
  std::vector<Vector2> places{centre};
  for (int k = 0; k < options.rays; ++k) {
    const double angle = options.rays == 1 ? 0 : std::numbers::pi / 4 * k / (options.rays - 1);
    const Vector2 u(std::cos(angle), std::sin(angle));
    for (double t = options.step_mm; fits(centre + t * u); t += options.step_mm) places.emplace_back(centre + t * u);
  }
  return places;
}

FiguresOfMerit evaluate_figures_of_merit(const EvalCase& eval_case, const FiguresOfMeritOptions& options,
                                         const Progress& progress) {
  const std::vector<Vector2> places = figure_of_merit_places(eval_case.sensor, options);
  PressSequence presses;
  for (const Vector2& p : places) presses.push_back({Press{p.x(), p.y(), options.radius_mm, options.force_N}});
  progress.say("  simulating");
  TwinOptions twin_options;
  twin_options.mesh_seed = options.mesh_seed;  // a mesh of its own: no inverse crime
  twin_options.noise_seed = options.seed;
  Twin twin(eval_case.sensor, twin_options);
  const SimulatedRun run = simulate_run(twin, presses);
  FiguresOfMerit result;
  result.places = static_cast<int>(places.size());
  FrameOptions frame_options;
  frame_options.track_contacts = false;  // each press on its own, as a grid's frames are
  for (Method method : options.methods) {
    progress.say(std::string("  ") + method_name(method));
    PipelineOptions pipeline_options;
    pipeline_options.method = method;
    const Pipeline pipeline(eval_case.sensor, pipeline_options);
    result.triangles = static_cast<long>(pipeline.model().mesh.triangle_count());
    Reconstructor reconstructor = pipeline.reconstructor(frame_options);
    reconstructor.set_reference(run.reference);
    const Vector2 centre = sheet_centre_mm(reconstructor.mesh());
    MethodMerit potential, pressure;
    potential.method = pressure.method = method;
    pressure.pressure = true;
    const auto score = [&](const Vector& image, std::size_t f, MethodMerit& m) {
      if (image.cwiseAbs().maxCoeff() == 0) {
        ++m.blank;
        return;
      }
      const GreitMerit merit = greit_figures_of_merit(reconstructor.mesh(), image, places[f], options.force_N);
      m.samples.push_back({places[f], (places[f] - centre).norm(), merit});
    };
    for (std::size_t f = 0; f < run.frames.size(); ++f) {
      reconstructor.process(run.frames[f]);
      if (is_linear(method)) score(reconstructor.image(), f, potential);
      score(reconstructor.pressure(), f, pressure);
    }
    if (is_linear(method)) {
      summarise(potential);
      result.methods.push_back(std::move(potential));
    }
    summarise(pressure);
    result.methods.push_back(std::move(pressure));
  }
  return result;
}

std::vector<std::string> write_figure_of_merit_plots(const EvalCase& eval_case, const FiguresOfMerit& merit,
                                                     const std::string& dir) {
  struct Figure {
    const char* stem;
    const char* title;
    const char* unit;
    double (*value)(const GreitMerit&);
  };
  const Figure figures[] = {
      {"ar", "amplitude response / its mean", "AR / mean AR", [](const GreitMerit& m) { return m.amplitude_response; }},
      {"pe", "position error, + inward", "PE (mm)", [](const GreitMerit& m) { return m.position_error_mm; }},
      {"res", "resolution", "RES", [](const GreitMerit& m) { return m.resolution; }},
      {"sd", "shape deformation", "SD", [](const GreitMerit& m) { return m.shape_deformation; }},
      {"rng", "ringing", "RNG", [](const GreitMerit& m) { return m.ringing; }},
  };
  std::filesystem::create_directories(dir);
  const std::string stem = dir + "/" + file_stem(eval_case.name) + "_merit_";
  std::vector<std::string> paths;
  for (const Figure& figure : figures) {
    std::vector<PlotSeries> series;
    for (std::size_t i = 0; i < merit.methods.size(); ++i) {
      const MethodMerit& m = merit.methods[i];
      if (m.samples.empty()) continue;
      const std::string label =
          std::string(method_name(m.method)) + (is_linear(m.method) ? (m.pressure ? " P" : " dphi") : "");
      PlotSeries s{label, {}, {}, series_colour(static_cast<int>(i)), true, {}};
      const double scale = figure.stem == std::string("ar") ? 1 / m.amplitude_response.mean : 1;
      // The places at one distance (one on each ray) averaged: a line per method.
      std::map<long, std::pair<double, int>> by_distance;  // 0.1 mm bins
      for (const MeritSample& sample : m.samples) {
        auto& [sum, count] = by_distance[std::lround(10 * sample.distance_from_centre_mm)];
        sum += scale * figure.value(sample.merit), ++count;
      }
      for (const auto& [bin, sum_count] : by_distance) {
        s.x.push_back(static_cast<double>(bin) / 10);
        s.y.push_back(sum_count.first / sum_count.second);
      }
      series.push_back(std::move(s));
    }
    if (series.empty()) continue;
    PlotOptions options;
    options.title = eval_case.name + ": " + figure.title;
    options.x_label = "distance from the centre (mm), mean over the rays";
    options.y_label = figure.unit;
    const std::string path = stem + figure.stem + ".png";
    write_png(render_line_plot(series, options), path);
    paths.push_back(path);
  }
  return paths;
}

}  // namespace emit
