// What the C entry points (deltri/triangle.h) share: the caller's arrays read with their counts
// checked, and one way of reporting, a status code and a one-line message instead of an exception.
#pragma once

#include <cstdio>
#include <exception>
#include <new>
#include <string>
#include <vector>

#define DELTRI_INTERNAL
#include "deltri/deltri.hpp"
#include "deltri/triangle.h"

namespace deltri {

[[noreturn]] inline void fail(int code, const std::string& message) { throw api::Error(code, message); }

// The values of an input array: `count` items of `per_item` values, from `list`, which may be NULL
// only when there are none, or (`optional`) always (then: none). With `per_item_name` the values
// per item are a count of the caller's too, and a message names both and gives their product.
template <class T>
std::vector<T> input_array(const T* list, long long count, long long per_item, const char* name, const char* count_name,
                           bool optional = false, const char* per_item_name = nullptr) {
  if (count < 0) fail(DELTRI_INPUT_ERROR, std::string(count_name) + " is " + std::to_string(count) + ", must not be negative");
  const long long values = count * per_item;
  if (values == 0 || (list == nullptr && optional)) return {};
  if (list == nullptr && per_item_name != nullptr)
    fail(DELTRI_INPUT_ERROR, std::string(name) + " is NULL but " + count_name + " times " + per_item_name + " is " +
                                 std::to_string(values) + " (" + std::to_string(count) + " times " + std::to_string(per_item) + ")");
  if (list == nullptr)
    fail(DELTRI_INPUT_ERROR, std::string(name) + " is NULL but " + count_name + " is " + std::to_string(count));
  return std::vector<T>(list, list + values);
}

inline void set_status(deltri_status* status, int code, const char* message) {
  if (!status) return;
  status->code = code;
  std::snprintf(status->message, sizeof status->message, "%s", message);
}

// Runs `job`, catching everything: returns DELTRI_OK, or the error's code with its message in `status`.
template <class Job>
int with_status(deltri_status* status, Job&& job) {
  try {
    job();
  } catch (const api::Error& e) {
    set_status(status, e.code(), e.what());
    return e.code();
  } catch (const std::bad_alloc&) {
    set_status(status, DELTRI_MEMORY_ERROR, "out of memory");
    return DELTRI_MEMORY_ERROR;
  } catch (const std::exception& e) {
    set_status(status, DELTRI_INTERNAL_ERROR, (std::string("internal error: ") + e.what()).c_str());
    return DELTRI_INTERNAL_ERROR;
  }
  set_status(status, DELTRI_OK, "");
  return DELTRI_OK;
}

}  // namespace deltri
