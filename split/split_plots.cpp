#include "split/split_plots.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "dataset/layout.hpp"
#include "dataset/window.hpp"
#include "core/durable_file.hpp"
#include "core/error.hpp"
#include "core/h5/file.hpp"
#include "core/plot/gnuplot.hpp"
#include "split/sections.hpp"

namespace haptex::split {
namespace fs = std::filesystem;

namespace {

constexpr const char* kSetNames[] = {"train", "val", "test"};
constexpr int kTraceStep = 10;  // plot every 10th acceleration sample: 1 kHz is plenty for a trace

void write_points(const fs::path& path, const MaterialWindows& m, const MaterialSplit& s, std::size_t sections) {
  std::ostringstream out;
  out << "set,speed_mm_s,force_n\n";
  for (std::size_t i = 0; i < m.start.size(); ++i) {
    const std::int64_t n = m.recording_samples.at(std::size_t(m.recording[i]));
    const int section = section_of(dataset::window_first_sample(m.start[i]), dataset::window_end_sample(m.start[i]), n, sections);
    const int set = section < 0 ? -1 : set_of_section(s.sections, section);
    if (set >= 0) out << kSetNames[set] << "," << m.speed[i] << "," << m.force[i] << "\n";
  }
  write_whole_file(path.string(), out.str());
}

void write_trace(const fs::path& path, const std::vector<float>& accel) {
  std::ostringstream out;
  out << "time_s,accel_m_s2\n";
  for (std::size_t i = 0; i < accel.size(); i += kTraceStep) out << double(i) / dataset::kSampleRateHz << "," << accel[i] << "\n";
  write_whole_file(path.string(), out.str());
}

void write_sections(const fs::path& path, const MaterialSplit& s, std::int64_t samples, std::size_t sections) {
  std::ostringstream out;
  out << "begin_s,end_s,set\n";
  for (std::size_t k = 0; k < sections; ++k)
    out << double(section_begin(k, samples, sections)) / dataset::kSampleRateHz << ","
        << double(section_begin(k + 1, samples, sections)) / dataset::kSampleRateHz << ","
        << kSetNames[set_of_section(s.sections, int(k))] << "\n";
  write_whole_file(path.string(), out.str());
}

constexpr const char* kSetColours[] = {"#9400d3", "#009e73", "#56b4e9"};

// Sections become shaded rectangles spanning the plot's height (graph coordinates), so the trace's
// scale does not matter; three empty plots give the legend its colours. gnuplot runs in the plot
// folder, so the script names its files by the material id alone.
std::string script_text(const std::string& id, const std::string& title, const std::string& terminal,
                        const MaterialSplit& s, std::int64_t samples, std::size_t sections) {
  std::ostringstream out;
  out << "set terminal " << terminal << " noenhanced size 1400,520" << (terminal == "pngcairo" ? " font ',10'" : "") << "\n"
      << "set output " << gnuplot::file(id + ".png") << "\n"
      << "set datafile separator ','\n"
      << "set multiplot layout 1,2 title " << gnuplot::text(title) << "\n"
      << "set key outside top center horizontal\n"
      << "set xlabel 'speed (mm/s)'; set ylabel 'normal force (N)'\n"
      << "plot for [i=1:3] " << gnuplot::file(id + "_points.csv") << " every ::1 using 2:(strcol(1) eq word('train val test', i) ? $3 : NaN)"
      << " with points pt 7 ps 0.3 lc rgb word('" << kSetColours[0] << " " << kSetColours[1] << " " << kSetColours[2]
      << "', i) title word('train val test', i)\n";
  for (std::size_t k = 0; k < sections; ++k) {
    const int set = set_of_section(s.sections, int(k));
    out << "set object " << k + 1 << " rect from " << double(section_begin(k, samples, sections)) / dataset::kSampleRateHz
        << ", graph 0 to " << double(section_begin(k + 1, samples, sections)) / dataset::kSampleRateHz << ", graph 1 fc rgb '"
        << kSetColours[set] << "' fs transparent solid 0.25 noborder behind\n";
  }
  out << "set xlabel 'time (s)'; set ylabel 'acceleration (m/s^2)'\n"
      << "plot " << gnuplot::file(id + "_trace.csv") << " every ::1 using 1:2 with lines lc rgb 'black' lw 0.5 notitle";
  for (int set = 0; set < 3; ++set)
    out << ", NaN with boxes fs solid 0.25 lc rgb '" << kSetColours[set] << "' title '" << kSetNames[set] << "'";
  out << "\nunset multiplot\n";
  return out.str();
}

}  // namespace

PlotResult write_split_plots(const std::string& dataset_path, const std::vector<MaterialWindows>& windows,
                             const std::vector<MaterialSplit>& splits, std::size_t sections, const std::string& directory,
                             const std::string& named) {
  const h5::Group materials = h5::File::open(dataset_path).root().open_group(dataset::layout::kMaterials);
  const std::string terminal = gnuplot::png_terminal();
  PlotResult result;
  for (std::size_t m = 0; m < windows.size(); ++m) {
    const fs::path base = fs::path(directory) / windows[m].id;
    const h5::Group recording = materials.open_group(windows[m].id).open_group(dataset::layout::kRecordings).open_group("0");
    const std::vector<float> accel = recording.open_dataset(dataset::layout::kAccel).read<float>();
    write_points(base.string() + "_points.csv", windows[m], splits[m], sections);
    write_trace(base.string() + "_trace.csv", accel);
    write_sections(base.string() + "_sections.csv", splits[m], std::int64_t(accel.size()), sections);
    const std::string& id = windows[m].id;
    write_whole_file(base.string() + ".gnuplot",
                     script_text(id, windows[m].name + ": train, validation and test (recording 0)",
                                 terminal.empty() ? "pngcairo" : terminal, splits[m], std::int64_t(accel.size()), sections));
    if (!terminal.empty() && gnuplot::draw(directory, id + ".gnuplot", id + ".png"))
      result.images.push_back((fs::path(named) / (id + ".png")).string());
  }
  if (terminal.empty()) result.note = "gnuplot is not installed: wrote the CSV data and gnuplot scripts to " + named + " only";
  else if (result.images.size() < windows.size()) result.note = "gnuplot failed on some plots; their CSV data and scripts are in " + named;
  return result;
}

}  // namespace haptex::split
