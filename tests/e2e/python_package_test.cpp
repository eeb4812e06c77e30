// python/ as a package a user installs: a venv made with --system-site-packages (Debian's numpy, h5py
// and torch), `pip install --no-index` of python/ with its in-tree build backend (no download, no
// setuptools), then tests/e2e/python_package_check.py run by the venv's python from a folder outside
// the repository: import haptex, its version, the kNN example as a module on the small pipeline's grid,
// the target smoothing against tests/golden/target_smoothing, the numpy forward pass and a
// press's latent against `haptex predict --json`, and the torch loader where torch imports.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/quick_models.hpp"
#include "tests/support/run_haptex.hpp"
#include "tests/support/small_pipeline.hpp"
#include "tests/support/temp_dir.hpp"

namespace haptex::test {
namespace {
namespace fs = std::filesystem;

const std::string kSource = std::string(HAPTEX_SCHEMA_DIR) + "/../";

// The venv with the package installed, made once per test program; `python` is empty when that failed
// (the failure is reported by the test that first asked).
struct Venv {
  TempDir dir;
  std::string work = dir.file("work"), python;
  CommandResult made, installed;
};

const Venv& venv() {
  static Venv v;
  static bool tried = false;
  if (!tried) {
    tried = true;
    fs::create_directory(v.work);
    v.made = run_program({"/usr/bin/python3", "-m", "venv", "--system-site-packages", v.dir.file("venv")}, v.work);
    if (v.made.exit_code != 0) return v;
    const std::string python = v.dir.file("venv") + "/bin/python";
    v.installed = run_program({python, "-m", "pip", "install", "--no-index", "--no-cache-dir", "--disable-pip-version-check", "-q",
                               kSource + "python"},
                              v.work);
    if (v.installed.exit_code == 0) v.python = python;
  }
  return v;
}

class PythonPackage : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!python_has("h5py, numpy")) GTEST_SKIP() << "python3-h5py is not installed (make deps installs it)";
    if (!python_has("ensurepip, venv"))
      GTEST_SKIP() << "python3-venv is not installed, so no venv to install the package into (make deps installs it)";
    const Venv& v = venv();
    ASSERT_EQ(v.made.exit_code, 0) << "python3 -m venv --system-site-packages: " << v.made.out << v.made.err;
    ASSERT_FALSE(v.python.empty()) << "pip install --no-index python/: " << v.installed.out << v.installed.err;
  }

  // python_package_check.py PART with the small pipeline and its quick models, run from the venv's
  // work folder (not the repository).
  static CommandResult check(const std::string& part) {
    const SmallPipeline& p = small_pipeline();
    const Venv& v = venv();
    return run_program({v.python, kSource + "tests/e2e/python_package_check.py", "--source", kSource, "--haptex", haptex_binary(),
                        "--dataset", p.dataset, "--split", p.split, "--model", quick_model(false), "--per-material-model",
                        quick_model(true), "--work", v.work, "--part", part},
                       v.work);
  }
};

TEST_F(PythonPackage, InstallsOfflineAndImportsFromAnyFolder) {
  const Venv& v = venv();
  const CommandResult r = run_program({v.python, "-c", "import haptex, haptex_data; print(haptex.__version__); print(haptex.__file__)"}, v.work);
  ASSERT_EQ(r.exit_code, 0) << r.out << r.err;
  const std::string version = r.out.substr(0, r.out.find('\n'));
  EXPECT_NE(r.out.find(v.dir.file("venv")), std::string::npos) << "not the installed package: " << r.out;
  EXPECT_EQ(run_haptex({"--version"}).out, "haptex " + version + "\n") << "the package's version is CMakeLists.txt's";
}

TEST_F(PythonPackage, ExamplesSmoothingNumpyModelAndPressLatentAgreeWithHaptex) {
  const CommandResult r = check("package");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("python package ok"), std::string::npos) << r.out << r.err;
  EXPECT_EQ(r.out.find("FAILED"), std::string::npos) << r.out;
}

TEST_F(PythonPackage, TheTorchLoaderGivesHaptexPredictsSpectra) {
  if (!python_has("torch")) GTEST_SKIP() << "python3-torch is not installed (make bench installs it); the torch loader is untested";
  const CommandResult r = check("torch");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("ok: torch vs haptex predict"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.out.find("python package ok"), std::string::npos) << r.out << r.err;
}

}  // namespace
}  // namespace haptex::test
