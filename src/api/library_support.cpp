#include <cstdio>
#include "api/library_support.h"

#include <algorithm>
#include <new>
#include <system_error>
#include <vector>

#include "options/switches.h"
#include "util/errors.h"

namespace deltri {
namespace {

std::string without_suffix(std::string text, const std::string& suffix) {
  if (text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0)
    text.erase(text.size() - suffix.size());
  return text;
}

// The long options the library takes: how many threads, and the paper's refinement policies.
bool is_library_option(const std::string& word) {
  for (const char* prefix : {"--threads=", "--algorithm=", "--interior-bound=", "--smooth="})
    if (word.rfind(prefix, 0) == 0) return true;
  return word == "--range-restricted" || word == "--corner-lopping" || word == "--smooth";
}

// The switches may end with words of the options the library takes beyond Triangle's letters
// ("pq30 --threads=4"); the letters come first. Other long options (files, pictures) are the
// command line's and refused.
std::vector<std::string> long_options_of(const std::string& switches, std::string& letters) {
  std::vector<std::string> options;
  std::size_t i = 0;
  while (i < switches.size()) {
    const std::size_t from = switches.find_first_not_of(" \t", i);
    if (from == std::string::npos) break;
    const std::size_t to = std::min(switches.find_first_of(" \t", from), switches.size());
    const std::string word = switches.substr(from, to - from);
    if (is_library_option(word)) {
      options.push_back(word);
    } else if (word.rfind("--", 0) == 0 || !letters.empty()) {
      throw api::Error(DELTRI_USAGE_ERROR, word + ": the switches are one word of letters, then optionally "
                                                  "--threads=N, --algorithm=NAME, --interior-bound=N, "
                                                  "--range-restricted, --corner-lopping, --smooth[=N]");
    } else {
      letters = word;
    }
    i = to;
  }
  return options;
}

}  // namespace

Options parse_library_switches(const std::string& given, bool size_function) {
  try {
    // A control character (a newline from a caller's buffer) would be echoed into a message of
    // more than one line; tabs separate words as spaces do.
    for (std::size_t i = 0; i < given.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(given[i]);
      if ((c < 0x20 && c != '\t') || c == 0x7f) {
        char what[96];
        std::snprintf(what, sizeof what, "the switches hold a control character (byte 0x%02x) at position %zu", c, i);
        throw api::Error(DELTRI_USAGE_ERROR, what);
      }
    }
    std::string letters;
    const std::vector<std::string> options = long_options_of(given, letters);
    if (!letters.empty() && letters[0] == '-') letters.erase(0, 1);
    std::vector<std::string> args = {"deltri"};
    if (!letters.empty()) args.push_back("-" + letters);
    args.insert(args.end(), options.begin(), options.end());
    args.push_back("input");
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());
    Switches sw = parse_switches(static_cast<int>(argv.size()), argv.data(), SwitchSource::Library);
    if (sw.caller_size_test && !size_function)
      throw api::Error(DELTRI_USAGE_ERROR, "u: a bare u asks for a size test, and none was given (or give a length, u0.05)");
    sw.quiet = true;
    return sw;  // the Options part: what the command line alone reads is dropped
  } catch (...) {
    rethrow_as_library_error();
  }
}

void rethrow_as_library_error() {
  using api::Error;
  try {
    throw;
  } catch (const Error&) {
    throw;
  } catch (const InputError& e) {
    throw Error(DELTRI_INPUT_ERROR, e.what());
  } catch (const UsageError& e) {
    throw Error(DELTRI_USAGE_ERROR, without_suffix(e.what(), " (see deltri -h)"));
  } catch (const MemoryError& e) {
    throw Error(DELTRI_MEMORY_ERROR, e.what());
  } catch (const std::bad_alloc&) {
    throw Error(DELTRI_MEMORY_ERROR, "out of memory");
  } catch (const std::system_error& e) {
    if (e.code() == std::errc::resource_unavailable_try_again) throw Error(DELTRI_MEMORY_ERROR, "out of memory (cannot start a thread)");
    throw Error(DELTRI_INTERNAL_ERROR, std::string("internal error: ") + e.what());
  } catch (const std::exception& e) {
    throw Error(DELTRI_INTERNAL_ERROR, std::string("internal error: ") + e.what());
  }
}

}  // namespace deltri
