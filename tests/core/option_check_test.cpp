// Every options struct checks itself (validate()), in one form of message, Ceres's:
// "<Struct>::<field> must be <what>, got <value>". Each struct's defaults pass; one wrong field of
// each is refused, naming the struct and the field.
#include "emit/core/option_check.hpp"

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "emit/acquire/frame_source.hpp"
#include "emit/calibrate/press_response_fit.hpp"
#include "emit/calibrate/sensor_calibration.hpp"
#include "emit/core/errors.hpp"
#include "emit/eval/pipeline_timing.hpp"
#include "emit/eval/real_evaluation.hpp"
#include "emit/eval/realistic_evaluation.hpp"
#include "emit/eval/sheet_evaluation.hpp"
#include "emit/eval/tracking_evaluation.hpp"
#include "emit/frame/contact_fitter.hpp"
#include "emit/frame/contact_tracker.hpp"
#include "emit/frame/reconstructor.hpp"
#include "emit/frame/reference.hpp"
#include "emit/live/dds_publisher.hpp"
#include "emit/live/live_loop.hpp"
#include "emit/mesh/generate_mesh.hpp"
#include "emit/mesh/slide_electrodes.hpp"
#include "emit/model/reconstruction_operator.hpp"
#include "emit/pipeline/pipeline.hpp"
#include "emit/pipeline/press_calibration.hpp"
#include "emit/render/field_image.hpp"
#include "emit/render/line_plot.hpp"
#include "emit/twin/realistic_sheet.hpp"
#include "emit/twin/twin.hpp"
#include "test_support.hpp"

namespace emit {
namespace {

TEST(OptionCheck, SaysWhichFieldOfWhichStructAndWhatItGot) {
  EXPECT_EQ(test::error_of([] { option_check::positive("MeshOptions", "element_size_mm", -0.5); }),
            "MeshOptions::element_size_mm must be positive, got -0.5");
  EXPECT_EQ(test::error_of([] { option_check::positive("A", "b", std::numeric_limits<double>::infinity()); }),
            "A::b must be positive, got inf");
  EXPECT_EQ(test::error_of([] { option_check::non_negative("A", "b", std::nan("")); }),
            "A::b must be 0 or more, got nan");
  EXPECT_EQ(test::error_of([] { option_check::within("A", "b", 1.5, 0, 1); }), "A::b must be in [0, 1], got 1.5");
  EXPECT_EQ(test::error_of([] { option_check::at_least("A", "b", 0, 1); }), "A::b must be at least 1, got 0");
  EXPECT_EQ(test::error_of([] { option_check::zero_or_positive("A", "b", -1, "the default"); }),
            "A::b must be 0 (the default) or positive, got -1");
  EXPECT_EQ(test::error_of([] { option_check::zero_or_positive("A", "b", 0, "the default"); }), "no error");
}

struct Case {
  std::string name;
  std::function<void()> defaults, wrong;
  std::string says;  ///< in the wrong one's message
};

TEST(OptionCheck, EveryOptionsStructChecksItself) {
  const std::vector<Case> cases = {
      {"OperatorOptions", [] { OperatorOptions{}.validate(); },
       [] {
         OperatorOptions o;
         o.lambda2 = -1;
         o.validate();
       },
       "OperatorOptions::lambda2 must be 0 (chosen from the spectrum) or positive, got -1"},
      {"MeshOptions", [] { MeshOptions{}.validate(); },
       [] {
         MeshOptions o;
         o.smoothing_steps = -1;
         o.validate();
       },
       "MeshOptions::smoothing_steps"},
      {"SlideOptions", [] { SlideOptions{}.validate(); },
       [] { SlideOptions{.rigid_mm = 0.6, .reach_mm = 0}.validate(); }, "SlideOptions::reach_mm"},
      {"SourceOptions", [] { SourceOptions{}.validate(); },
       [] {
         SourceOptions o;
         o.frames_per_s = -50;
         o.validate();
       },
       "SourceOptions::frames_per_s"},
      {"FrameOptions", [] { FrameOptions{}.validate(); },
       [] {
         FrameOptions o;
         o.threshold_fraction = 1;
         o.validate();
       },
       "FrameOptions::threshold_fraction must be a fraction in (0, 1)"},
      {"ReferenceOptions", [] { ReferenceOptions{}.validate(); },
       [] {
         ReferenceOptions{0, 0.01}.validate();
       },
       "ReferenceOptions::capture_frames must be at least 1, got 0"},
      {"FitOptions", [] { FitOptions{}.validate(); },
       [] {
         FitOptions o;
         o.max_contacts = 0;
         o.validate();
       },
       "max_contacts"},
      {"RealisticSheetOptions", [] { RealisticSheetOptions{}.validate(); },
       [] {
         RealisticSheetOptions o;
         o.field = 2;
         o.validate();
       },
       "field"},
      {"TwinOptions", [] { TwinOptions{}.validate(); },
       [] {
         TwinOptions o;
         o.cover_blur_mm = -1;
         o.validate();
       },
       "TwinOptions::cover_blur_mm"},
      {"PressCalibrationOptions", [] { PressCalibrationOptions{}.validate(); },
       [] {
         PressCalibrationOptions o;
         o.lambda2 = std::nan("");
         o.validate();
       },
       "PressCalibrationOptions::lambda2"},
      {"PipelineOptions", [] { PipelineOptions{}.validate(); },
       [] { PipelineOptions{.method = Method::paper, .lambda2 = -3, .cache_dir = "", .excluded = {}}.validate(); },
       "PipelineOptions::lambda2 must be 0 (the method's) or positive, got -3"},
      {"PressResponseFitOptions", [] { PressResponseFitOptions{}.validate(); },
       [] {
         PressResponseFitOptions o;
         o.degrees.clear();
         o.validate();
       },
       ""},
      {"SensorCalibrationOptions", [] { SensorCalibrationOptions{}.validate(); },
       [] {
         SensorCalibrationOptions o;
         o.max_iterations = 0;
         o.validate();
       },
       "max_iterations"},
      {"PlotOptions", [] { PlotOptions{}.validate(); },
       [] {
         PlotOptions o;
         o.width_px = 0;
         o.validate();
       },
       "PlotOptions::width_px"},
      {"FieldImageOptions", [] { FieldImageOptions{}.validate(); },
       [] {
         FieldImageOptions o;
         o.min_value = 1, o.max_value = 0;
         o.validate();
       },
       "FieldImageOptions::max_value must be above min_value"},
      {"PipelineTimingOptions", [] { PipelineTimingOptions{}.validate(); },
       [] {
         PipelineTimingOptions o;
         o.seconds_per_figure = 0;
         o.validate();
       },
       "PipelineTimingOptions::seconds_per_figure"},
      {"RealEvalOptions", [] { RealEvalOptions{}.validate(550, "presses"); },
       [] {
         RealEvalOptions o;
         o.calibration_presses = 0;
         o.validate(550, "presses");
       },
       ""},
      {"EvalOptions", [] { EvalOptions{}.validate(); },
       [] {
         EvalOptions o;
         o.methods.clear();
         o.validate();
       },
       "EvalOptions::methods"},
      {"RealisticEvalOptions", [] { RealisticEvalOptions{}.validate(); },
       [] {
         RealisticEvalOptions o;
         o.counts.test_presses = 0;
         o.validate();
       },
       "test_presses"},
      {"DdsOptions", [] { DdsOptions{}.validate(); },
       [] {
         DdsOptions{"emit", 300}.validate();
       },
       "--dds-domain 300"},
      {"LiveOptions", [] { LiveOptions{}.validate(); },
       [] {
         LiveOptions o;
         o.reference.drift_rate = 2;
         o.validate();
       },
       "ReferenceOptions::drift_rate"},
      {"TrackerOptions", [] { TrackerOptions{}.validate(); },
       [] {
         TrackerOptions o;
         o.jump_sigmas = 0;
         o.validate();
       },
       "TrackerOptions::jump_sigmas must be positive, got 0"},
      {"TrackingEvalOptions", [] { TrackingEvalOptions{}.validate(); },
       [] {
         TrackingEvalOptions o;
         o.max_frames = 10;
         o.validate();
       },
       "TrackingEvalOptions::max_frames"},
  };
  EXPECT_EQ(cases.size(), 23u) << "every *Options struct of include/emit";
  for (const Case& c : cases) {
    EXPECT_EQ(test::error_of(c.defaults), "no error") << c.name << "'s defaults";
    const std::string said = test::error_of(c.wrong);
    EXPECT_NE(said, "no error") << c.name;
    EXPECT_NE(said.find(c.says), std::string::npos) << c.name << ": " << said;
  }
}

}  // namespace
}  // namespace emit
