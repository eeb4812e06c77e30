#pragma once
// Outputs that belong together (a model and its training log, a split manifest and its plots, a
// gelsight file and its contact sheets) appear together or not at all (docs/architecture.md, "Outputs
// are atomic"). Each is first written whole under a temporary name and synced; commit_together then
// checks every final name, renames them one by one, and when a rename fails (a folder of the user's
// appeared at a name meanwhile, a rename refused) takes back every one already renamed, the earlier
// versions it replaced included, before it rethrows. Only when all are in place are the earlier
// versions removed. A signal taken meanwhile waits (hold_temporaries).
#include <functional>
#include <string>
#include <vector>

namespace haptex {

// One output of a set, written and synced under a temporary name. All but finish() run under
// hold_temporaries, so none of them may make or forget a temporary (core/temporary_name.hpp).
class StagedOutput {
 public:
  virtual ~StagedOutput() = default;
  // Syncs what was written (failed: a full disk), without renaming.
  virtual void finish() = 0;
  // Throws haptex::Error (bad_input) when the final name may no longer take the output: a file or
  // folder of the user's appeared there, or the earlier one changed so that it may not be replaced.
  virtual void check_place() const = 0;
  // Renames the output to its final name; an earlier version there is kept aside (RENAME_EXCHANGE),
  // not yet removed. Throws haptex::Error as check_place, or (failed) when the rename fails.
  virtual void put_in_place() = 0;
  // Undoes put_in_place: the output back under its temporary name, the earlier version (or nothing)
  // back under the final name.
  virtual void take_back() noexcept = 0;
  // The set is in place: removes the earlier version kept aside.
  virtual void drop_earlier() = 0;
};

// An output of an earlier run that the set retires without a successor: a `--no-plots --force`
// split's old plots, a `--no-sheets --force` extraction's old contact sheets. Kept aside while the
// set is renamed (put back when it fails) and removed with the earlier versions; left alone when
// `retire` says it is not haptex's to remove (asked in finish and again in check_place).
class EarlierOutput : public StagedOutput {
 public:
  // Before any work: refuses (bad_input, naming path) an earlier output at path that `retire` says is
  // not haptex's to remove (a file of the user's among the old plots), since the new output would
  // appear beside an old companion it no longer matches. `what` names it ("the plot folder").
  static void require_retirable(const std::string& path, const std::function<bool(const std::string& path)>& retire,
                                const std::string& what, const std::string& fix);

  EarlierOutput(std::string path, std::function<bool(const std::string& path)> retire);
  ~EarlierOutput() override;
  EarlierOutput(const EarlierOutput&) = delete;
  EarlierOutput& operator=(const EarlierOutput&) = delete;

  void finish() override;
  void check_place() const override;
  void put_in_place() override;
  void take_back() noexcept override;
  void drop_earlier() override;

 private:
  std::string path_, aside_;  // aside_: a temporary the earlier output is moved onto
  std::function<bool(const std::string&)> retire_;
  mutable bool retiring_ = false;
  bool moved_ = false;
  int fd_ = -1;  // the lock of aside_ (core/temporary_name.hpp)
};

// finish(), check_place(), put_in_place() of every output (null ones left out), then drop_earlier(); on
// an error, every output already in place is taken back (last first) and the error rethrown.
void commit_together(const std::vector<StagedOutput*>& outputs);

// How an output and its companion name each other (a model and its training log, a gelsight file and
// its contact sheets): `path` relative to the folder of `file`, so the record holds wherever the two
// are moved together. An output replaced with --force names the companions its run wrote, which go
// with it when the new run writes them elsewhere or not at all, while they still hold the bytes it
// recorded and name it back (docs/architecture.md, "Outputs are atomic").
std::string relative_to_folder_of(const std::string& path, const std::string& file);
// The path again, from what relative_to_folder_of recorded in (or beside) `file`.
std::string resolved_beside(const std::string& recorded, const std::string& file);

}  // namespace haptex
