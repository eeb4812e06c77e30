#include "evaluate/baselines/hatt_published.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "core/naming.hpp"
#include "tests/support/npy.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::evaluate {
namespace {

namespace fs = std::filesystem;

// A minimal valid HaTT model file: one AR(2) model on each corner of [0, 100] x [0, 2].
std::string model_xml(const std::string& material) {
  std::string corners;
  const double speeds[] = {0, 100, 0, 100}, forces[] = {0, 0, 2, 2};
  for (int i = 0; i < 4; ++i)
    corners += "<model><modNum>" + std::to_string(i + 1) +
               "</modNum><ARcoeff><value>1</value><value>-0.5</value><value>0.3</value></ARcoeff>"
               "<ARlsf><value>0.9</value><value>1.6</value></ARlsf><var>" + (i == 3 ? "0.1" : "0") +
               "</var><speedMod>" + std::to_string(speeds[i]) + "</speedMod><forceMod>" + std::to_string(forces[i]) +
               "</forceMod></model>";
  return "<modelSet texture=\"3\"><material>" + material +
         "</material><SampleRate>10000</SampleRate><mu>0.2</mu><numMod>4</numMod><numTri>2</numTri>"
         "<maxSpeed>100</maxSpeed><maxForce>2</maxForce>"
         "<speedList type=\"array\"><value>0</value><value>100</value><value>0</value><value>100</value></speedList>"
         "<forceList type=\"array\"><value>0</value><value>0</value><value>2</value><value>2</value></forceList>"
         "<tri type=\"array\"><value>1</value><value>2</value><value>4</value></tri>"
         "<tri type=\"array\"><value>1</value><value>4</value><value>3</value></tri>"
         "<numARCoeff>2</numARCoeff><numMACoeff>0</numMACoeff>" +
         corners + "</modelSet>";
}

void write(const test::TempDir& dir, const std::string& name, const std::string& text) {
  std::ofstream(dir.file(name)) << text;
}

// A folder like the toolkit's: three materials, a licence and an image folder beside them.
class PublishedDir : public ::testing::Test {
 protected:
  void SetUp() override {
    write(dir_, "Models_Brick 2.xml", model_xml("Brick 2"));
    write(dir_, "Models_Cork.xml", model_xml("Cork"));
    write(dir_, "Models_Sandpaper 220.xml", model_xml("Sandpaper 220"));
    write(dir_, "PENN-LICENSE.pdf", "%PDF");
    fs::create_directory(dir_.path() / "images");
  }
  std::string error_of(std::string_view material) {
    try {
      find_hatt_model_file(dir_.path(), material);
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), Error::Kind::bad_input);
      return e.what();
    }
    ADD_FAILURE() << "no error for " << material;
    return "";
  }
  test::TempDir dir_;
};

TEST_F(PublishedDir, NamesAndIdsFindTheSameFile) {
  for (const char* name : {"Brick 2", "brick_2", "BRICK-2", "  Brick 2 "})
    EXPECT_EQ(find_hatt_model_file(dir_.path(), name).filename(), "Models_Brick 2.xml") << name;
  EXPECT_EQ(find_hatt_model_file(dir_.path(), "sandpaper_220").filename(), "Models_Sandpaper 220.xml");
  const ar::PiecewiseArModel model = load_hatt_published(dir_.path(), "cork");
  EXPECT_EQ(model.set().material, "Cork");
  EXPECT_EQ(model.order(), 2u);
}

TEST_F(PublishedDir, NotFoundNamesTheDirectoryTheMaterialAndTheClosestFiles) {
  const std::string message = error_of("Brik 2");
  EXPECT_NE(message.find(dir_.path().string()), std::string::npos) << message;
  EXPECT_NE(message.find("'Brik 2'"), std::string::npos) << message;
  EXPECT_NE(message.find("brik_2"), std::string::npos) << message;
  // Brick 2 is one letter away: listed first.
  EXPECT_NE(message.find("the closest are Models_Brick 2.xml, "), std::string::npos) << message;
  EXPECT_EQ(message.find("PENN-LICENSE"), std::string::npos) << message;
  // "Brick" alone is another material (id brick, not brick_2).
  EXPECT_NE(error_of("Brick").find("no HaTT model file"), std::string::npos);
}

TEST_F(PublishedDir, SeveralMatchesAreNamed) {
  write(dir_, "Models_brick_2.xml", model_xml("Brick 2"));
  const std::string message = error_of("Brick 2");
  EXPECT_NE(message.find("2 model files match"), std::string::npos) << message;
  EXPECT_NE(message.find("Models_Brick 2.xml"), std::string::npos) << message;
  EXPECT_NE(message.find("Models_brick_2.xml"), std::string::npos) << message;
}

TEST_F(PublishedDir, RenamedFilesAreFoundByTheirMaterial) {
  write(dir_, "velvet_copy_2014.xml", model_xml("Velvet"));
  write(dir_, "notes.xml", "<notes>not a model</notes>");
  write(dir_, "broken.xml", "<modelSet><material>Velvet");
  EXPECT_EQ(find_hatt_model_file(dir_.path(), "Velvet").filename(), "velvet_copy_2014.xml");
  // Two files that both hold Velvet: ambiguous again.
  write(dir_, "velvet_other.xml", model_xml("Velvet"));
  EXPECT_NE(error_of("Velvet").find("velvet_copy_2014.xml, velvet_other.xml"), std::string::npos);
}

TEST_F(PublishedDir, AFileNamedForOneMaterialHoldingAnotherIsRefused) {
  write(dir_, "Models_Wood.xml", model_xml("Book"));
  try {
    load_hatt_published(dir_.path(), "Wood");
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("Models_Wood.xml"), std::string::npos) << message;
    EXPECT_NE(message.find("'Book'"), std::string::npos) << message;
  }
}

TEST_F(PublishedDir, NotADirectory) {
  EXPECT_THROW(find_hatt_model_file(dir_.path() / "Models_Cork.xml", "Cork"), Error);
  EXPECT_THROW(find_hatt_model_file(dir_.path() / "absent", "Cork"), Error);
  test::TempDir empty;
  try {
    find_hatt_model_file(empty.path(), "Cork");
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no .xml files"), std::string::npos) << e.what();
  }
}

TEST(HattPublished, EveryToolkitModelIsFoundByItsMaterialName) {
  const std::string shared = test::shared_data_dir();
  const fs::path dir = fs::path(shared) / "hatt" / "models";
  if (shared.empty() || !fs::is_directory(dir)) GTEST_SKIP() << "../shared/data/hatt/models is absent: skipped";
  std::size_t found = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() != ".xml") continue;
    std::string material = entry.path().stem().string().substr(std::string("Models_").size());
    const ar::PiecewiseArModel model = load_hatt_published(dir, material);
    EXPECT_EQ(material_id(model.set().material), material_id(material));
    EXPECT_EQ(find_hatt_model_file(dir, material_id(material)), entry.path());
    ++found;
  }
  EXPECT_EQ(found, 60u);
}

}  // namespace
}  // namespace haptex::evaluate
