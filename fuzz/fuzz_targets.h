// libFuzzer entry point shared by the fuzz targets (fuzz/*_fuzz.cc) and the plain replay driver
// (replay_main.cc). A target returns 0 for every input it handles as specified: accepted, or
// rejected with InputError. Anything else (another exception, a crash, a sanitizer report, a
// broken postcondition, which the targets turn into abort()) is a finding.
#pragma once

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
