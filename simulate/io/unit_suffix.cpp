#include "unit_suffix.h"

#include <sstream>
#include <vector>

namespace dp::io {

namespace {

// Unit words as they appear in key suffixes, '_' separating numerator and
// denominator parts (kg_m3, m_s2, w_mk).
bool is_unit_word(const std::string& w) {
  static const std::set<std::string> kUnits = {
      "m",  "mm", "cm", "km", "um", "in", "ft", "s",   "ms",  "us",  "min", "h",  "kg", "g",    "mg",
      "c",  "k",  "f",  "pa", "kpa", "hpa", "bar", "atm", "deg", "rad", "hz", "m2", "m3", "s2", "cm3",
      "w",  "mk", "kgk", "j", "kj", "l",  "ml", "mph", "kmh", "percent"};
  return kUnits.count(w) > 0;
}

std::vector<std::string> words(const std::string& key) {
  std::vector<std::string> out;
  std::stringstream in(key);
  for (std::string w; std::getline(in, w, '_');) out.push_back(w);
  return out;
}

// How many trailing words of `key` are unit words.
std::size_t unit_word_count(const std::vector<std::string>& w) {
  std::size_t n = 0;
  while (n < w.size() && is_unit_word(w[w.size() - 1 - n])) ++n;
  return n;
}

std::string join(const std::vector<std::string>& w, std::size_t count) {
  std::string s;
  for (std::size_t i = 0; i < count; ++i) s += (i ? "_" : "") + w[i];
  return s;
}

}  // namespace

std::optional<std::string> key_in_expected_unit(const std::string& key, const std::set<std::string>& known) {
  const std::vector<std::string> kw = words(key);
  const std::size_t ku = unit_word_count(kw);
  if (ku == 0 || ku == kw.size()) return std::nullopt;
  const std::string stem = join(kw, kw.size() - ku);
  for (const std::string& candidate : known) {
    if (candidate == key) continue;
    const std::vector<std::string> cw = words(candidate);
    const std::size_t cu = unit_word_count(cw);
    if (cu == 0 || cu == cw.size()) continue;
    if (join(cw, cw.size() - cu) == stem) return candidate;
  }
  return std::nullopt;
}

}  // namespace dp::io
