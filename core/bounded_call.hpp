#pragma once
// A library call that damaged input can keep from ever returning. libhdf5 1.10 (Debian 12's) loops
// forever, at full CPU, reading a variable-length value whose global heap collection holds a zeroed
// object header (review 14, F9): no error comes back to catch. So such calls run under a BoundedCall,
// and once one has spent kStuckCallSeconds of its thread's processor time without returning, a
// watchdog thread hands the handler the program set an error naming the file and the place read (bad
// input: the file is damaged). Processor time,
// not wall time: a slow disk or a network file system waits without using it.
//
// The library itself never prints or exits: without a handler (a program that links haptex and set
// none) a BoundedCall does nothing. haptex's command line sets one (apps/run_main.cpp) that removes
// the run's unfinished outputs, reports the error as any other (exit 2 for bad input) and ends the
// process, since the stuck thread cannot be unwound.
#include <functional>
#include <string>

#include "core/error.hpp"

namespace haptex {

// More than any one read of a value haptex makes can take: the largest, one encoded frame or a
// dataset of names, takes milliseconds.
constexpr double kStuckCallSeconds = 10;

class BoundedCall {
 public:
  // A read of `where` in `file`. Calls do not nest.
  BoundedCall(const std::string& file, const std::string& where);
  ~BoundedCall();
  BoundedCall(const BoundedCall&) = delete;
  BoundedCall& operator=(const BoundedCall&) = delete;

 private:
  bool armed_ = false;
};

// Called on the watchdog thread with the stuck call's error (bad input, "FILE: WHERE: reading it does
// not end ..."); it must end the process: the watchdog stops watching once it has called it. Set it
// once, early.
void on_stuck_call(std::function<void(const Error&)> handler);

}  // namespace haptex
