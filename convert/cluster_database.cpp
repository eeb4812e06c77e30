#include "convert/cluster_database.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <regex>
#include <set>
#include <tuple>

#include "convert/csv_table.hpp"
#include "convert/recording_checks.hpp"
#include "convert/resampling.hpp"
#include "core/error.hpp"
#include "core/naming.hpp"
#include "core/input_file.hpp"
#include "core/signal/butterworth.hpp"
#include "core/signal/resample.hpp"
#include "core/signal/sosfilt.hpp"
#include "core/text/format.hpp"
#include "dataset/layout.hpp"

namespace haptex::convert {
namespace fs = std::filesystem;
namespace layout = dataset::layout;
namespace {

// The position is differentiated for the speed: its 100 Hz steps are low-passed first at 10 Hz
// (a machine's stroke changes speed slower; quantisation noise differentiated does not).
constexpr double kPositionLowpassHz = 10.0;
// The file name's velocity against the median speed of the stroke (where it moves faster than a
// quarter of it): a position in other units or a misnamed file is off by far more.
constexpr double kSpeedTolerance = 0.25;
// Half a second: the speed filter's padding and a stroke worth keeping.
constexpr double kShortestTakeS = 0.5;

// One file's time stamps and the columns asked for.
struct Series {
  std::string path, sha256;
  std::vector<double> times;
  std::vector<std::vector<double>> columns;
};

Series read_series(const std::string& path, const std::vector<std::string>& names, int nominal_hz, std::uintmax_t max_bytes) {
  std::vector<std::string> wanted = {"time"};
  wanted.insert(wanted.end(), names.begin(), names.end());
  std::string header;
  for (const auto& name : wanted) header += (header.empty() ? "" : ",") + name;
  CsvTable table = read_csv_table(path, max_bytes, [&](const std::string& column) {
    return std::find(wanted.begin(), wanted.end(), column) != wanted.end();
  });
  Series s{path, table.sha256, {}, {}};
  for (const std::string& name : wanted) {
    auto column = table.columns.find(name);
    if (column == table.columns.end())
      throw input_error(path, "line 1", "the header has no '" + name + "' column",
                        "The database's files have the header " + header);
    (name == "time" ? s.times : s.columns.emplace_back()) = std::move(column->second);
  }
  const double rate = check_stamps(path, "time", s.times, table.lines.at("time"));
  if (rate > 1.1 * nominal_hz || rate < 0.5 * nominal_hz)
    throw input_error(path, "column 'time'",
                      text::format("the samples come at %.0f Hz on average, not about %d Hz as the database's do", rate,
                                   nominal_hz),
                      "Check that the time column is in seconds and the file is the take's own");
  return s;
}

// numpy.gradient(x) * rate: central differences inside, one-sided at the ends.
std::vector<double> derivative(const std::vector<double>& x, double rate) {
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t a = i == 0 ? 0 : i - 1, b = std::min(i + 1, x.size() - 1);
    d[i] = (x[b] - x[a]) / double(b - a) * rate;
  }
  return d;
}

// The tool's speed in mm/s, on a 100 Hz grid over the position file's stamps (`grid` gets its times).
std::vector<double> stroke_speed(const Series& position, std::vector<double>& grid) {
  static const signal::Sos sos = signal::butter_lowpass_hz(4, kPositionLowpassHz, kClusterPositionHz);
  const double start = position.times.front();
  const std::size_t count = std::size_t(std::floor((position.times.back() - start) * kClusterPositionHz)) + 1;
  for (std::size_t k = 0; k < count; ++k) grid.push_back(start + double(k) / kClusterPositionHz);
  std::vector<double> v[2];
  for (std::size_t c = 0; c < 2; ++c)
    v[c] = derivative(signal::sosfiltfilt(sos, signal::interpolate_uniform(position.times, position.columns[c], start,
                                                                           kClusterPositionHz, count)),
                      kClusterPositionHz);
  std::vector<double> speed(count);
  for (std::size_t i = 0; i < count; ++i) speed[i] = std::hypot(v[0][i], v[1][i]);
  return speed;
}

void check_speed(const std::vector<double>& speed, const ClusterTake& take) {
  std::vector<double> moving;
  for (double v : speed)
    if (v > 0.25 * take.velocity_mm_s) moving.push_back(v);
  const std::string where = "columns 'X', 'Y'";
  if (moving.empty())
    throw input_error(take.position, where, "the tool does not move", "Give the take's own position file");
  auto middle = moving.begin() + std::ptrdiff_t(moving.size() / 2);
  std::nth_element(moving.begin(), middle, moving.end());
  if (std::abs(*middle / take.velocity_mm_s - 1.0) > kSpeedTolerance)
    throw input_error(take.position, where,
                      text::format("the stroke's median speed is %.1f mm/s where the file name says %d mm/s",
                                   *middle, take.velocity_mm_s),
                      "Check that the position is in millimetres and the file is the take's own");
}

std::string take_name(const ClusterTake& t) {
  return text::format("%d_%d_%d_%d_%d.csv", t.texture, t.direction_deg, t.velocity_mm_s, t.force_mn, t.repeat);
}

}  // namespace

std::vector<ClusterTake> find_cluster_takes(const std::string& root) {
  std::error_code ec;
  const fs::path sensor = fs::is_directory(fs::path(root) / "sensor_data" / "accel", ec) ? fs::path(root) / "sensor_data"
                                                                                          : fs::path(root);
  if (!fs::is_directory(sensor / "accel", ec))
    throw input_error(root, "", "holds no sensor_data/accel folder",
                      "Give the Cluster database's folder (the one holding sensor_data/ and images/)");
  static const std::regex name(R"((\d{1,6})_(\d{1,3})_(\d{1,4})_(\d{1,6})_(\d{1,3})\.csv)");
  std::vector<ClusterTake> takes;
  for (const auto& entry : fs::directory_iterator(sensor / "accel", ec)) {
    const std::string file = entry.path().filename().string();
    if (entry.path().extension() != ".csv") continue;
    require_regular_file(entry.path().string());  // a dangling link or a FIFO is refused, not skipped
    std::smatch m;
    if (!std::regex_match(file, m, name))
      throw input_error(entry.path().string(), "", "is not named TEXTURE_DIRECTION_VELOCITY_FORCE_REPEAT.csv",
                        "Keep the database's file names (e.g. 0_135_40_500_0.csv)");
    ClusterTake t{std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4]), std::stoi(m[5]),
                  entry.path().string(), (sensor / "force" / file).string(), (sensor / "position" / file).string()};
    if (t.velocity_mm_s == 0 || t.force_mn == 0)
      throw input_error(t.accel, "file name", "names a velocity or force of 0", "Keep the database's file names");
    for (const std::string* partner : {&t.force, &t.position}) {
      if (fs::exists(fs::symlink_status(*partner, ec))) require_regular_file(*partner);  // a FIFO or dangling link, by name
      if (!fs::is_regular_file(*partner, ec))
        throw input_error(*partner, "", "is missing: the take " + file + " needs its accel, force and position files",
                          "Copy the database's sensor_data folder whole");
    }
    takes.push_back(std::move(t));
  }
  if (ec) throw input_error((sensor / "accel").string(), "", "cannot list the folder (" + ec.message() + ")", "Check its permissions");
  if (takes.empty()) throw input_error((sensor / "accel").string(), "", "holds no take (*.csv)", "Give the database's folder");
  const auto key = [](const ClusterTake& t) {
    return std::tie(t.texture, t.direction_deg, t.velocity_mm_s, t.force_mn, t.repeat);
  };
  std::sort(takes.begin(), takes.end(), [&](const ClusterTake& a, const ClusterTake& b) { return key(a) < key(b); });
  return takes;
}

std::string cluster_material(int texture, const std::map<int, std::string>& names) {
  const auto it = names.find(texture);
  return it != names.end() ? it->second : "cluster " + std::to_string(texture);
}

std::vector<int> check_cluster_materials(const std::vector<ClusterTake>& takes, const std::map<int, std::string>& names,
                                         const std::string& names_file) {
  std::set<int> textures;
  for (const ClusterTake& take : takes) textures.insert(take.texture);
  std::vector<int> unused;
  for (const auto& [texture, name] : names)
    if (!textures.count(texture)) unused.push_back(texture);
  if (!names.empty() && unused.size() == names.size()) {
    std::string present;
    for (const int t : textures) present += (present.empty() ? "" : ", ") + std::to_string(t);
    throw input_error(names_file, "", "names none of the database's textures (it holds " + present + ")",
                      "Give the names file of this database, naming its texture numbers");
  }
  std::map<std::string, int> by_id;
  for (const ClusterTake& take : takes) {
    const std::string material = cluster_material(take.texture, names);
    const auto [at, added] = by_id.emplace(material_id(material), take.texture);
    if (added || at->second == take.texture) continue;
    const int named = names.count(take.texture) ? take.texture : at->second, other = named == take.texture ? at->second : take.texture;
    throw input_error(names_file, "texture " + std::to_string(named),
                      "'" + names.at(named) + "' makes the material id '" + at->first + "' that texture " + std::to_string(other) +
                          (names.count(other) ? " is given too" : " has by default (as 'cluster " + std::to_string(other) + "')"),
                      "Give each texture a name of its own, or name texture " + std::to_string(other) + " too");
  }
  return unused;
}

Recording read_cluster_take(const ClusterTake& take, const std::map<int, std::string>& names, std::uintmax_t max_bytes) {
  const Series accel = read_series(take.accel, {"X", "Y", "Z"}, kClusterAccelHz, max_bytes);
  const Series force = read_series(take.force, {"force"}, kClusterForceHz, max_bytes);
  const Series position = read_series(take.position, {"X", "Y"}, kClusterPositionHz, max_bytes);
  const double start = std::max({accel.times.front(), force.times.front(), position.times.front()});
  const double span = std::min({accel.times.back(), force.times.back(), position.times.back()}) - start;
  if (!(span >= kShortestTakeS))
    throw input_error(take.accel, "column 'time'",
                      text::format("the take's accel, force and position files overlap for %.3g s", std::max(0.0, span)),
                      text::format("A take needs at least %.1f s of all three", kShortestTakeS));

  Recording r;
  r.material = cluster_material(take.texture, names);
  for (const auto& [quantity, unit] : kExpectedUnits) r.units[quantity] = unit;
  r.source_path = take.accel;
  const char* axes[] = {"accel_x", "accel_y", "accel_z"};
  for (std::size_t c = 0; c < 3; ++c) r.channels[axes[c]] = accel.columns[c];
  apply_units(r, "accel", "g", "columns 'X', 'Y', 'Z'");
  r.channels[layout::kForceNormal] = force.columns[0];
  std::vector<double> speed_times;
  r.channels[layout::kSpeed] = stroke_speed(position, speed_times);
  check_speed(r.channels[layout::kSpeed], take);
  resample_stamped(r, {{"accel time", accel.times, {axes[0], axes[1], axes[2]}, kClusterAccelHz},
                       {"force time", force.times, {layout::kForceNormal}, kClusterForceHz},
                       {"position time", speed_times, {layout::kSpeed}, kClusterPositionHz}});

  r.source_sha256 = accel.sha256;
  r.source_texts = {{layout::kForceSourceFile, take.force}, {layout::kForceSourceSha256, force.sha256},
                    {layout::kPositionSourceFile, take.position}, {layout::kPositionSourceSha256, position.sha256}};
  r.source_numbers = {{layout::kClusterTexture, take.texture}, {layout::kStrokeDirection, take.direction_deg},
                      {layout::kCommandedSpeed, take.velocity_mm_s}, {layout::kCommandedForce, take.force_mn * 1e-3},
                      {layout::kRepeat, take.repeat}};
  check_channels(r, [&](const std::string& channel) { return take_name(take) + ": " + channel; });
  return r;
}

}  // namespace haptex::convert
