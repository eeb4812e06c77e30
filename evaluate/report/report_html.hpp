#pragma once
// report.html beside report.md (docs/evaluate.md, "report.html"): one self-contained page a browser
// opens from anywhere. The Markdown report, every table sortable and every chart embedded, and per
// material a listening section: the start of its first test section as recorded, as the model's
// stitched signal and as the AR baseline rendered it, as audio players (16-bit WAV at 48 kHz, written
// by haptex, embedded), with the press's peak image and the three spectra of its middle window.
//
// Loudness: a material's three clips share one full scale, the loudest sample of the three rounded up
// (render/wav_writer.hpp, rounded_full_scale), so they compare with each other and nothing clips; each
// material has its own, so a quiet one is as audible as a loud one. The page states each scale.
//
// A script on the page sorts a table by the column clicked, and records what loaded: every image that
// fails and every audio element's duration, in the element with id "load-check" (JSON), which the
// tests read from a headless browser (tests/e2e/report_page_test.cpp); the frame, players and
// spectra are page/'s, which `haptex view` shares.
#include <string>

#include "evaluate/evaluation_results.hpp"

namespace haptex::evaluate {

// `markdown`: report.md's text; `folder`: where its charts (PNG) are, read and embedded.
std::string report_html(const Evaluation& e, const std::string& markdown, const std::string& folder);

}  // namespace haptex::evaluate
