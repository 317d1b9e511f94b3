// arpsim tracker import: a head-motion dataset (one sample per line; columns,
// axes and units stated) converted into a trace file, with a summary of the
// motion and warnings for what a human head does not do.
#include <cstdio>
#include <optional>
#include <string>

#include "CommonOptions.hpp"
#include "Commands.hpp"
#include "common/InputError.hpp"
#include "common/OutputPaths.hpp"
#include "tracker/DatasetImport.hpp"
#include "tracker/MotionSummary.hpp"
#include "tracker/TraceEdit.hpp"
#include "tracker/TraceFile.hpp"

namespace arp::app {

namespace {

struct ImportArgs {
  std::string in, out;
  tracker::DatasetLayoutOptions layout;
  bool drop_repeats = false;
  std::optional<double> resample_hz;  // given 0 is refused with the rate's range, not read as "not given"
};

int run_import(const ImportArgs& a) {
  const tracker::DatasetLayout layout = tracker::dataset_layout(a.layout);
  if (a.resample_hz) tracker::check_resample_rate(*a.resample_hz);  // before the dataset is read
  check_output_paths({{"trace", a.out}}, {{"dataset", a.in}});
  std::vector<tracker::PoseSample> samples = tracker::read_head_motion_dataset(a.in, layout);
  const tracker::MotionSummary before = tracker::summarize_motion(samples);
  std::printf("arpsim tracker import: %s (%s axes, time in %s)\n", a.in.c_str(), a.layout.axes.c_str(), a.layout.time_unit.c_str());
  for (const auto& l : tracker::describe(before)) std::printf("  %s\n", l.c_str());
  for (const auto& w : tracker::motion_warnings(before)) std::fprintf(stderr, "arpsim tracker import: warning: %s\n", w.c_str());
  if (a.drop_repeats) {
    const size_t n = tracker::drop_repeats(samples);
    std::printf("  --drop-repeats: %zu repeated samples dropped, %zu kept\n", n, samples.size());
    if (samples.size() < 2) throw InputError(a.in, "", "fewer than two samples differ; nothing to import");
  }
  if (a.resample_hz) {
    samples = tracker::resample_as_asked(samples, *a.resample_hz);
    std::printf("  --resample: %zu samples at %.1f Hz (spherical linear interpolation)\n", samples.size(), *a.resample_hz);
  }
  if (a.drop_repeats || a.resample_hz)
    for (const auto& l : tracker::describe(tracker::summarize_motion(samples))) std::printf("  now: %s\n", l.c_str());
  tracker::write_trace_csv(a.out, samples);
  std::printf("  -> %s (%zu samples, %.3f s)\n", a.out.c_str(), samples.size(),
              static_cast<double>(samples.back().time_ps - samples.front().time_ps) * 1e-12);
  return 0;
}

}  // namespace

Subcommand add_tracker_import_command(CLI::App& tracker) {
  auto im = std::make_shared<ImportArgs>();
  CLI::App* import = tracker.add_subcommand(
      "import", "Convert a head-motion dataset (one sample per line; columns, axes and units stated) into a trace file, "
                "with a summary of the motion and warnings for what a human head does not do (docs/tracker.md)");
  import->add_option("dataset", im->in, "Dataset file")->required();
  import->add_option("trace", im->out, "Trace file to write")->required()->check(output_name());
  import->add_option("--time-unit", im->layout.time_unit, "Unit of the timestamp: s, ms, us, ns")->capture_default_str();
  import->add_option("--axes", im->layout.axes,
                     "The dataset's axes: gl (right-handed, y up, -z forward, as arpsim), unity (left-handed, +z forward), "
                     "corbillon (z up, +x forward: Corbillon et al. 2017), or where its x, y, z point in arpsim's frame, "
                     "e.g. +x,+y,-z")
      ->capture_default_str();
  import->add_option("--columns", im->layout.columns,
                     "ROLE=COLUMN,... by number from 1 or header name; roles t, frame, qw, qx, qy, qz (quaternion) or "
                     "rx, ry, rz (angles about the dataset's x, y, z). Default t=1,frame=2,qw=3,qx=4,qy=5,qz=6");
  import->add_flag("--scalar-last", im->layout.scalar_last, "The quaternion columns are x y z w (t=1,frame=2,qx=3,qy=4,qz=5,qw=6)");
  import->add_option("--euler", im->layout.euler, "Euler angles: the intrinsic order, outermost first (e.g. yxz for yaw, pitch, roll in a y-up frame)");
  import->add_option("--angle-unit", im->layout.angle_unit, "Unit of Euler angles: deg or rad")->capture_default_str();
  import->add_flag("--drop-repeats", im->drop_repeats, "Drop samples that repeat the one before (a logger faster than its tracker)");
  import->add_option("--resample", im->resample_hz, "Resample to this rate, Hz (spherical linear interpolation; for low-rate logs)");
  return {import, [im] { return run_import(*im); }};
}

}  // namespace arp::app
