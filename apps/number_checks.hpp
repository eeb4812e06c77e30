#pragma once
// Checks of numeric options. CLI11 reads "nan", "inf" and 1e999 as numbers; its range checks let NaN
// through and answer infinity with a bound of 309 digits. These refuse both first, saying so. odd_number
// reads a whole number as CLI11 does (decimal, 0x hexadecimal, 0 octal) and refuses an even one.
#include <CLI/CLI.hpp>

namespace haptex::apps {

CLI::Validator finite_number();        // every floating-point option has it (run_main.cpp); at most 3.4e38 in size
CLI::Validator positive_number();      // finite and > 0, at least 1.2e-38 (a normal 32-bit float)
CLI::Validator non_negative_number();  // finite and >= 0
CLI::Validator odd_number();           // a whole number not divisible by 2
CLI::Validator seed_number();          // a whole number from 0 to 2^53, which JSON (and so every record of it) keeps exact

}  // namespace haptex::apps
