#include "qa/check.hpp"

#include <sstream>

#include "qa/catalog.hpp"

namespace haptex::qa {
namespace {

// The JSON report lists at most this many failing places per check; the count says how many there were.
constexpr std::size_t kMaxWhere = 100;

}  // namespace

std::string_view to_string(Severity severity) { return severity == Severity::error ? "error" : "warning"; }

std::string_view to_string(Status status) {
  switch (status) {
    case Status::pass: return "pass";
    case Status::fail: return "fail";
    case Status::skip: return "skip";
  }
  return "?";
}

CheckTally::CheckTally(std::string_view id, std::string items) : id_(id), items_(std::move(items)) {
  check_info(id);  // an unknown id is a programming error: fail at once
}

void CheckTally::fail(const std::string& where, const std::string& what) { failures_.emplace_back(where, what); }

void CheckTally::skip(const std::string& why) { skips_.push_back(why); }

CheckResult CheckTally::result() const {
  const CheckInfo& info = check_info(id_);
  CheckResult r{std::string(id_), info.severity, Status::pass, {}, std::string(info.hint), {}};
  const std::string skipped =
      skips_.empty() ? "" : "; " + std::to_string(skips_.size()) + " not checked (" + skips_.front() + ")";
  if (!failures_.empty()) {
    r.status = Status::fail;
    const auto& [where, what] = failures_.front();
    r.message = where + ": " + what;
    if (failures_.size() > 1) r.message += " (and " + std::to_string(failures_.size() - 1) + " more)";
    for (std::size_t i = 0; i < failures_.size() && i < kMaxWhere; ++i) r.where.push_back(failures_[i].first);
  } else if (passed_ > 0) {
    // "1 recording", "2 recordings" (one-word nouns; longer phrases stay as written).
    const bool singular = passed_ == 1 && items_.back() == 's' && items_.find(' ') == std::string::npos;
    // "presses" -> "press", "hashes" -> "hash", "recordings" -> "recording" (review 9: "1 presse")
    const std::size_t cut = items_.ends_with("sses") || items_.ends_with("shes") ? 2 : 1;
    const std::string items = singular ? items_.substr(0, items_.size() - cut) : items_;
    r.message = std::to_string(passed_) + " " + items + (pass_message_.empty() ? " checked" : ": " + pass_message_);
    r.message += skipped;
  } else {
    r.status = Status::skip;
    r.message = skips_.empty() ? "no " + items_ + " to check" : skips_.front();
    if (skips_.size() > 1) r.message += " (and " + std::to_string(skips_.size() - 1) + " more)";
  }
  return r;
}

CheckResult make_result(std::string_view id, Status status, std::string message, std::vector<std::string> where) {
  const CheckInfo& info = check_info(id);
  return CheckResult{std::string(id), info.severity, status, std::move(message), std::string(info.hint),
                     std::move(where)};
}

std::string number(double value, int precision) {
  std::ostringstream out;
  out.precision(precision);
  out << value;
  return out.str();
}

}  // namespace haptex::qa
