// Issue 11 point 8: a table of hostile inputs per reader (XML and CSV recordings, JSON manifests,
// trajectories, HDF5 files with wrong dtypes and shapes, images, videos). Each case asserts what the
// README promises: exit code 2, one message naming the file, no crash, and no output or NAME.partial left.
#include <gtest/gtest.h>
#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <set>

#include "core/gzip.hpp"
#include "core/sha256.hpp"
#include "core/text/utf8.hpp"
#include "dataset/press_images.hpp"
#include "dataset/vlen_bytes.hpp"
#include "tests/hostile/hostile_support.hpp"
#include "tests/support/cluster_tree.hpp"
#include "tests/support/mutations.hpp"
#include "tests/support/quick_models.hpp"
#include "tests/support/sample_recording.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

struct HostileCase {
  std::string reader, name;
  std::function<std::string(const TempDir&)> make;  // writes the hostile file, returns its path
  std::function<std::vector<std::string>(const TempDir&, const std::string&)> command;
  std::string says;  // a word the message must hold besides the file's name
};

std::string write(const TempDir& dir, const std::string& name, const std::string& bytes) {
  std::ofstream(dir.file(name), std::ios::binary) << bytes;
  return dir.file(name);
}

std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

// ---- the readers and what makes them hostile

std::string good_xml() { return sample_recording_xml({.seconds = 0.3}); }

auto convert_it = [](const TempDir& dir, const std::string& file) {
  return std::vector<std::string>{"convert", "hatt", file, "-o", dir.file("out.h5")};
};

std::vector<HostileCase> xml_cases() {
  auto xml = [](std::string name, std::function<std::string()> text, std::string says) {
    return HostileCase{"HaTT XML", name, [=](const TempDir& d) { return write(d, "rec.xml", text()); }, convert_it, says};
  };
  return {
      xml("empty", [] { return ""; }, "rec.xml"),
      xml("truncated in half", [] { const std::string x = good_xml(); return x.substr(0, x.size() / 2); }, "XML"),
      xml("binary garbage", [] { return std::string("\x00\xff\xfe\x01garbage\x00", 12); }, "XML"),
      xml("entity expansion (billion laughs)", [] {
        return "<?xml version=\"1.0\"?><!DOCTYPE r [<!ENTITY a \"aaaaaaaaaa\"><!ENTITY b \"&a;&a;&a;&a;&a;&a;&a;&a;\">]><r>&b;</r>";
      }, "DTD"),
      xml("100000 nested elements", [] { std::string s; for (int i = 0; i < 100000; ++i) s += "<a>"; return s; }, "XML"),
      xml("NaN sample", [] { return replace_once(good_xml(), "<value>", "<value>NaN</value><value>"); }, "NaN"),
      xml("1e-400 sample", [] { return replace_once(good_xml(), "<value>", "<value>1e-400</value><value>"); }, "out of range"),
      xml("1e999 sample", [] { return replace_once(good_xml(), "<value>", "<value>1e999</value><value>"); }, "out of range"),
      xml("text sample", [] { return replace_once(good_xml(), "<value>", "<value>twelve</value><value>"); }, "not a number"),
      xml("no material", [] {
        std::string x = good_xml();
        const auto open = x.find("<material>"), close = x.find("</material>") + 11;
        return x.erase(open, close - open);
      }, "material"),
      xml("material not UTF-8", [] { return replace_once(good_xml(), "<material>", "<material>\xc3\x28"); }, "UTF-8"),
  };
}

std::vector<HostileCase> gzip_cases() {
  auto gz = [](std::string name, std::function<std::string()> bytes, std::string says) {
    return HostileCase{"gzip-compressed HaTT XML", name, [=](const TempDir& d) { return write(d, "rec `x` 'y'.xml.gz", bytes()); },
                       convert_it, says};
  };
  const std::string good = gzip::compress(good_xml(), 1);
  return {
      gz("cut short", [=] { return good.substr(0, good.size() / 2); }, "cut short"),
      gz("header only", [=] { return good.substr(0, 10); }, "cut short"),
      gz("damaged CRC", [=] { std::string b = good; b[b.size() - 8] = char(b[b.size() - 8] ^ 1); return b; }, "damaged"),
      gz("garbage after the data", [=] { return good + "PK\x03\x04"; }, "not gzip data"),
      {"gzip-compressed HaTT XML", "expands past --max-bytes",
       [](const TempDir& d) { return write(d, "bomb.xml.gz", gzip::compress(std::string(std::size_t(64) << 20, ' '), 9)); },
       [](const TempDir& d, const std::string& file) {
         return std::vector<std::string>{"convert", "hatt", file, "-o", d.file("out.h5"), "--max-bytes", "1000000"};
       },
       "--max-bytes"},
      gz("NaN inside", [] { return gzip::compress(replace_once(good_xml(), "<value>", "<value>NaN</value><value>"), 1); }, "NaN"),
  };
}

std::vector<HostileCase> csv_cases() {
  auto csv = [](std::string name, std::function<std::string()> text, std::string says, std::string file = "cork_0.csv") {
    return HostileCase{"recording CSV", name, [=](const TempDir& d) { return write(d, file, text()); }, convert_it, says};
  };
  const std::string good = sample_recording_csv({.seconds = 0.3});
  return {
      csv("empty", [] { return ""; }, "empty"),
      csv("header only", [=] { return good.substr(0, good.find('\n') + 1); }, "cork_0.csv"),
      csv("ragged row", [=] { return replace_once(good, "\n", "\n1,2\n"); }, "fields"),
      csv("NaN sample", [=] {
        std::string text = good;
        const auto row = text.find('\n') + 1;  // the first sample's first field
        text.replace(row, text.find(',', row) - row, "nan");
        return text;
      }, "line 2"),
      csv("name not UTF-8", [=] { return good; }, "UTF-8", "Caf\xe9_0.csv"),
  };
}

// One good Cluster take in a folder whose name holds quotes and back-quotes; `damage` spoils one of its
// files (or writes a names file) and returns that file.
std::vector<HostileCase> cluster_cases() {
  const std::string db = "db `ls` \"x\" 'y'", take = "3_0_40_500_0.csv";
  auto in_db = [=](const TempDir& d, const std::string& folder) { return d.file(db + "/sensor_data/" + folder + "/" + take); };
  auto cluster = [=](std::string name, std::function<std::string(const TempDir&)> damage, std::string says,
                     std::vector<std::string> extra = {}) {
    auto make = [=](const TempDir& d) {
      write_cluster_tree(d.file(db), {{3, 0, 40, 500, 0}});
      return damage(d);
    };
    auto command = [=](const TempDir& d, const std::string& file) {
      std::vector<std::string> args = {"convert", "cluster", d.file(db), "-o", d.file("out.h5")};
      for (const auto& e : extra) args.push_back(e == "FILE" ? file : e);
      return args;
    };
    return HostileCase{"Cluster take", name, make, command, says};
  };
  auto overwrite = [=](std::string folder, std::string bytes) {
    return [=](const TempDir& d) { std::ofstream(in_db(d, folder), std::ios::binary) << bytes; return in_db(d, folder); };
  };
  return {
      cluster("empty accel file", overwrite("accel", ""), "empty"),
      cluster("accel cut inside a row", overwrite("accel", "time,X,Y,Z\n0.000999,0.1"), "fields"),
      cluster("binary garbage", overwrite("force", std::string("time,force\n\x00\xff,\x01\n", 16)), "line 2"),
      cluster("NaN force", overwrite("force", "time,force\n0.000999,nan\n0.001209,0.5\n"), "not a finite number"),
      cluster("no time column", overwrite("position", "t,X,Y\n0,1,2\n"), "time"),
      cluster("over --max-bytes", [=](const TempDir& d) { return in_db(d, "accel"); }, "max-bytes", {"--max-bytes", "1000"}),
      cluster("names file not UTF-8", [=](const TempDir& d) { return write(d, "names.csv", "id,name\n3,Caf\xe9\n"); }, "UTF-8",
              {"--names", "FILE"}),
      // Issue 32, classes 15 and 17.
      cluster("accel file a dangling link", [=](const TempDir& d) {
        fs::remove(in_db(d, "accel"));
        fs::create_symlink(d.file("nowhere.csv"), in_db(d, "accel"));
        return in_db(d, "accel");
      }, "link to a file that does not exist"),
      cluster("names JSON key twice", [=](const TempDir& d) { return write(d, "names.json", R"({"3": "a", "3": "b"})"); }, "given twice",
              {"--names", "FILE"}),
      cluster("names file empty", [=](const TempDir& d) { return write(d, "names.csv", ""); }, "names no texture", {"--names", "FILE"}),
      cluster("names file /dev/zero", [=](const TempDir& d) {
        fs::create_symlink("/dev/zero", d.file("names.csv"));
        return d.file("names.csv");
      }, "not a regular file", {"--names", "FILE"}),
  };
}

std::vector<HostileCase> manifest_cases() {
  auto train_with = [](const TempDir& dir, const std::string& file) {
    return quick_train_args(small_pipeline().dataset, file, dir.file("m.h5"));
  };
  auto manifest = [=](std::string name, std::function<std::string()> text, std::string says) {
    return HostileCase{"split manifest", name, [=](const TempDir& d) { return write(d, "split.json", text()); }, train_with, says};
  };
  auto edited = [](std::function<void(nlohmann::json&)> change) {
    return [=] {
      nlohmann::json doc = read_json(small_pipeline().split);
      change(doc);
      return doc.dump();
    };
  };
  return {
      manifest("empty", [] { return ""; }, "JSON"),
      manifest("truncated", [] { const std::string s = file_bytes(small_pipeline().split); return s.substr(0, s.size() / 2); }, "JSON"),
      manifest("not UTF-8", [] { return std::string("{\"a\": \"\xff\"}"); }, "JSON"),
      manifest("100000 nested arrays", [] { return std::string(100000, '[') + std::string(100000, ']'); }, "split.json"),
      manifest("sections as strings", edited([](nlohmann::json& d) { d["materials"][0]["sections"]["train"] = {"a", "b"}; }), "schema"),
      manifest("sections not a number", edited([](nlohmann::json& d) { d["parameters"]["sections"] = "many"; }), "schema"),
      manifest("negative section", edited([](nlohmann::json& d) { d["materials"][0]["sections"]["val"].push_back(-3); }), "split.json"),
      manifest("no materials", edited([](nlohmann::json& d) { d["materials"] = nlohmann::json::array(); }), "split.json"),
  };
}

std::vector<HostileCase> trajectory_cases() {
  auto predict_with = [](const TempDir&, const std::string& file) {
    return std::vector<std::string>{"predict", quick_model(), "--material", small_material(), "--csv", file};
  };
  auto trajectory = [=](std::string name, std::string text, std::string says) {
    return HostileCase{"trajectory CSV", name, [=](const TempDir& d) { return write(d, "t.csv", text); }, predict_with, says};
  };
  return {
      trajectory("empty", "", "t.csv"),
      trajectory("no force column", "speed\n100\n", "force"),
      trajectory("NaN force", "force,speed\nnan,100\n", "line 2"),
      trajectory("missing field", "force,speed\n1\n", "line 2"),
      trajectory("negative speed", "force,speed\n1,-5\n", "negative"),
      trajectory("binary", std::string("\x00\x01\x02\xff", 4), "t.csv"),
  };
}

// HDF5 files haptex wrote, each with one object of the wrong kind, type or shape.
// A dataset whose press images `damage` spoils (in every press, so training meets one), with the
// split made before the damage (split's gate refuses images of another layout itself); `haptex train`
// decodes them.
std::vector<HostileCase> press_image_cases() {
  auto images = [](std::string name, std::function<void(Edit&, const std::string& press)> damage, std::string says) {
    return HostileCase{"dataset press images", name,
                       [=](const TempDir& d) {
                         const std::string file = copy_into(d, small_pipeline().dataset, "d.h5");
                         {
                           Edit e(file);
                           for (const std::string& m : e.group("materials").children())
                             for (const std::string& j : e.group("materials/" + m + "/presses").children())
                               damage(e, "materials/" + m + "/presses/" + j);
                         }
                         nlohmann::json manifest = read_json(small_pipeline().split);
                         manifest["dataset"]["sha256"] = sha256_file(file);
                         write_json(d.file("s.json"), manifest);
                         return file;
                       },
                       [](const TempDir& d, const std::string& file) { return quick_train_args(file, d.file("s.json"), d.file("m.h5")); },
                       says};
  };
  // Frames replaced by `bytes` (every element), kept a dataset of encoded images.
  auto frames_of = [](std::vector<std::uint8_t> bytes) {
    return [=](Edit& e, const std::string& press) {
      const std::size_t n = e.dataset(press + "/frames").shape()[0];
      e.remove(press + "/frames");
      h5::Group g = e.group(press);
      dataset::VlenBytesWriter w(g, "frames");
      for (std::size_t i = 0; i < n; ++i) w.append(bytes);
      w.dataset().set_attr("channel_order", "RGB");
      w.dataset().set_attr("encoding", "png");
    };
  };
  const std::vector<std::uint8_t> png = dataset::encode_png(cv::Mat(120, 160, CV_8UC3, cv::Scalar(10, 20, 30)));  // the presses' size
  std::vector<std::uint8_t> huge = png;  // the IHDR's width and height at 100000 x 100000, its CRC made to fit
  for (int k : {16, 20}) huge[std::size_t(k)] = 0x00, huge[std::size_t(k) + 1] = 0x01, huge[std::size_t(k) + 2] = 0x86, huge[std::size_t(k) + 3] = 0xA0;
  const uLong crc = crc32(0, &huge[12], 17);
  for (int k = 0; k < 4; ++k) huge[std::size_t(29 + k)] = std::uint8_t(crc >> (24 - 8 * k));
  return {
      images("frames that are no image", frames_of({'G', 'I', 'F', '8', '9', 'a', 0, 0}), "neither a JPEG nor a PNG"),
      images("a frame of another size than the press states",
             frames_of(dataset::encode_png(cv::Mat(60, 80, CV_8UC3, cv::Scalar(10, 20, 30)))), "the press's width and height"),
      images("a frame whose header claims 100000 x 100000", frames_of(huge), "over 64 megapixels"),
      images("a PNG cut short", frames_of(std::vector<std::uint8_t>(png.begin(), png.begin() + std::ptrdiff_t(png.size() / 2))),
             "does not decode"),
      images("frames stored as pixels (gelsight/1)", [](Edit& e, const std::string& press) {
        e.remove(press + "/frames");
        e.group(press).write_array<std::uint8_t>("frames", std::vector<std::uint8_t>(2 * 60 * 80 * 3, 7), {2, 60, 80, 3});
      }, "/frames/@encoding: attribute missing"),  // the train gate's layout check (review 18, F9)
  };
}

std::vector<HostileCase> hdf5_cases() {
  auto dataset_edit = [](std::string name, std::function<void(Edit&)> change, std::string says) {
    return HostileCase{"dataset HDF5", name,
                       [=](const TempDir& d) {
                         const std::string file = copy_into(d, small_pipeline().dataset, "d.h5");
                         Edit edit(file);
                         change(edit);
                         return file;
                       },
                       [](const TempDir& d, const std::string& file) { return std::vector<std::string>{"split", file, "-o", d.file("s.json")}; },
                       says};
  };
  auto model_edit = [](std::string name, std::function<void(Edit&)> change, std::string says) {
    return HostileCase{"model HDF5", name,
                       [=](const TempDir& d) {
                         const std::string file = copy_into(d, quick_model(), "m.h5");
                         Edit edit(file);
                         change(edit);
                         return file;
                       },
                       [](const TempDir&, const std::string& file) {
                         return std::vector<std::string>{"predict", file, "--material", small_material(), "--normal-force", "1", "--speed", "100"};
                       },
                       says};
  };
  return {
      HostileCase{"dataset HDF5", "not HDF5", [](const TempDir& d) { return write(d, "d.h5", "plain text"); },
                  [](const TempDir& d, const std::string& f) { return std::vector<std::string>{"split", f, "-o", d.file("s.json")}; }, "HDF5"},
      dataset_edit("no /windows", [](Edit& e) { e.remove("windows"); }, "windows"),
      dataset_edit("start as float", [](Edit& e) {
        const auto v = e.dataset("windows/start").read<double>();
        e.replace<double>("windows/start", v, {v.size()});
      }, "windows"),
      dataset_edit("start of another length", [](Edit& e) {
        auto v = e.dataset("windows/start").read<std::int64_t>();
        v.pop_back();
        e.replace<std::int64_t>("windows/start", v, {v.size()});
      }, "/windows/start"),
      dataset_edit("action 1-D", [](Edit& e) {
        const auto v = e.dataset("windows/action").read<float>();
        e.replace<float>("windows/action", v, {v.size()});
      }, "/windows/action"),
      dataset_edit("format attribute an integer", [](Edit& e) {
        e.remove("@haptex_format");
        e.root().set_attr("haptex_format", 7);
      }, "haptex_format"),
      dataset_edit("recording named 'x'", [](Edit& e) {
        const std::string id = read_json(small_pipeline().split)["materials"][0]["id"];
        e.copy("materials/" + id + "/recordings/0", "materials/" + id + "/recordings/x");
      }, "/recordings/x: is not numbered"),  // split's layout gate (review 20, F4)
      model_edit("weights as int64", [](Edit& e) {
        const auto v = e.dataset("nets/0/predictor/layers/0/weight").read<float>();
        const h5::Shape shape = e.dataset("nets/0/predictor/layers/0/weight").shape();
        std::vector<std::int64_t> ints(v.size(), 1 << 30);
        e.replace<std::int64_t>("nets/0/predictor/layers/0/weight", ints, shape);
      }, "m.h5"),
      model_edit("scale of another length", [](Edit& e) { e.replace<float>("normalisation/target_scale", {1, 2, 3}, {3}); }, "target_scale"),
      model_edit("config not JSON", [](Edit& e) {
        e.remove("@config");
        e.root().set_attr("config", "{not json");
      }, "config"),
      model_edit("feature size 10^9", [](Edit& e) {
        e.remove("feature_spec@size");
        e.group("feature_spec").set_attr("size", std::int64_t(1000000000));
      }, "size"),
      model_edit("no materials", [](Edit& e) { e.remove("materials"); }, "materials"),
      // Review 19, F2: the second material was unreachable, the empty id accepted.
      model_edit("an id given twice", [](Edit& e) {
        for (const char* list : {"materials/ids", "materials/names"}) {
          std::vector<std::string> values = e.dataset(list).read_strings();
          values.back() = values.front();
          e.remove(list);
          e.group("materials").write_strings(std::string(list).substr(10), values);
        }
      }, "/materials/ids[1]: '" + small_material() + "' is given twice"),
      model_edit("names swapped (review 20, F2)", [](Edit& e) {
        std::vector<std::string> names = e.dataset("materials/names").read_strings();
        std::swap(names.front(), names.back());
        e.remove("materials/names");
        e.group("materials").write_strings("names", names);
      }, "is not the id of the material's name"),
      model_edit("an empty id", [](Edit& e) {
        std::vector<std::string> ids = e.dataset("materials/ids").read_strings();
        ids.back() = "";
        e.remove("materials/ids");
        e.group("materials").write_strings("ids", ids);
      }, "is not the id of the material's name"),
  };
}

std::vector<HostileCase> image_cases() {
  auto predict_image = [](const TempDir&, const std::string& file) {
    return std::vector<std::string>{"predict", quick_model(), "--image", file, "--normal-force", "1", "--speed", "100"};
  };
  auto image = [=](std::string name, std::string bytes, std::string file, std::string says) {
    return HostileCase{"press image", name, [=](const TempDir& d) { return write(d, file, bytes); }, predict_image, says};
  };
  return {
      image("empty PNG", "", "p.png", "image"),
      image("text named .png", "hello", "p.png", "image"),
      image("PNG cut after its header", std::string("\x89PNG\r\n\x1a\n\x00\x00\x00\x0dIHDR\x00\x00\x01\x00\x00\x00\x01\x00\x08\x02", 26), "p.png", "image"),
      image("JPEG start only", std::string("\xff\xd8\xff", 3), "p.jpg", "image"),
  };
}

std::vector<HostileCase> video_cases() {
  auto extract = [](const TempDir& d, const std::string& file) {
    return std::vector<std::string>{"capture", "extract", file, "-o", d.file("g.h5")};
  };
  auto video = [=](std::string name, std::string bytes, std::string file) {
    return HostileCase{"press video", name, [=](const TempDir& d) { return write(d, file, bytes); }, extract, file};
  };
  return {
      video("empty .mkv", "", "v.mkv"),
      video("random bytes .mp4", std::string(4096, '\x5a'), "v.mp4"),
      video("text .avi", "RIFF....AVI not really", "v.avi"),
  };
}

// ---- the test

std::set<std::string> names_in(const TempDir& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(dir.path())) names.insert(entry.path().string());
  return names;
}

std::vector<HostileCase> corpus() {
  std::vector<HostileCase> all;
  for (auto part : {xml_cases(), gzip_cases(), csv_cases(), cluster_cases(), manifest_cases(), trajectory_cases(), hdf5_cases(),
                    press_image_cases(), image_cases(), video_cases()})
    all.insert(all.end(), part.begin(), part.end());
  return all;
}

TEST(HostileCorpus, EveryReaderRefusesEveryCaseCleanly) {
  const std::vector<HostileCase> cases = corpus();
  for (const HostileCase& c : cases) {
    SCOPED_TRACE(c.reader + ": " + c.name);
    const TempDir dir;
    const std::string file = c.make(dir);
    const std::set<std::string> before = names_in(dir);
    const CommandResult r = run_haptex(c.command(dir, file));
    expect_refusal(r, {text::printable(fs::path(file).filename().string()), c.says});  // named as a terminal shows it
    EXPECT_LT(std::count(r.err.begin(), r.err.end(), '\n'), 3) << "one message, not a cascade: " << r.err;
    EXPECT_EQ(names_in(dir), before) << "the command left a file behind";
  }
  std::cout << cases.size() << " hostile cases\n";
}

}  // namespace
}  // namespace haptex::test
