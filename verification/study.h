// A study: plain data computed once per process and shared by the verification cases that
// judge it and the report sections that draw it (every number the report prints is a case's
// measurement or is labelled an illustration). A study is a function returning a const
// reference to a lazily computed, cached struct:
//
//   const SlopeStudy& slope_study() {
//     static const Study<SlopeStudy> study("undamped COR slope", compute_slope_study);
//     return study.get();
//   }
//
// Contract of Study<T>::get():
//   * the first caller computes; concurrent callers (run_cases runs cases on several threads)
//     wait for it and then share the one result; later calls return it at no cost;
//   * if the computation throws, the failure is stored and every call (the first included)
//     throws StudyError naming the study and the reason; it is not recomputed. A case that
//     reads a failed study is therefore a failed case with that reason (run_case turns the
//     exception into a failed outcome), and a report section that reads it shows an error box
//     naming the study; nothing crashes and nothing is silent.
#pragma once

#include <functional>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

namespace ivv::verification {

// Thrown by Study<T>::get() when the study's computation failed.
class StudyError : public std::runtime_error {
 public:
  StudyError(const std::string& study, const std::string& reason)
      : std::runtime_error("study '" + study + "' failed: " + reason), study_(study) {}
  const std::string& study() const { return study_; }

 private:
  std::string study_;
};

template <class T>
class Study {
 public:
  Study(std::string name, std::function<T()> compute)
      : name_(std::move(name)), compute_(std::move(compute)) {}
  Study(const Study&) = delete;
  Study& operator=(const Study&) = delete;

  const std::string& name() const { return name_; }

  // The study's data, computed on first use (thread-safe); throws StudyError if it failed.
  const T& get() const {
    std::call_once(once_, [this] {
      try {
        value_.emplace(compute_());
      } catch (const std::exception& e) {
        error_ = e.what();
      } catch (...) {
        error_ = "an exception that is not a std::exception";
      }
      if (!value_ && error_.empty()) error_ = "no result";
    });
    if (!value_) throw StudyError(name_, error_);
    return *value_;
  }

 private:
  std::string name_;
  std::function<T()> compute_;
  mutable std::once_flag once_;
  mutable std::optional<T> value_;
  mutable std::string error_;
};

}  // namespace ivv::verification
