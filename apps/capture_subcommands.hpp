#pragma once
// The three parts of `haptex capture` (apps/capture_command.cpp ties them together), one file each.
#include <memory>

#include "apps/command.hpp"

namespace haptex::apps {

class CaptureSubcommand {
 public:
  virtual ~CaptureSubcommand() = default;
  virtual CLI::App* declare(CLI::App& capture) = 0;  // adds itself to `capture`
  virtual int run(const GlobalOptions& global) = 0;
  virtual bool ends_on_signals_itself() const { return false; }  // as Command's
};

std::unique_ptr<CaptureSubcommand> make_capture_devices();  // apps/capture_devices.cpp
std::unique_ptr<CaptureSubcommand> make_capture_record();   // apps/capture_record.cpp
std::unique_ptr<CaptureSubcommand> make_capture_extract();  // apps/capture_extract.cpp

}  // namespace haptex::apps
