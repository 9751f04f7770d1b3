// What the fuzz harnesses share. Each harness defines LLVMFuzzerTestOneInput; built with clang's
// libFuzzer (HLR_FUZZ) it is a fuzzer, built otherwise it is linked with replay_main.cpp, which
// runs it once over every file of a corpus (the default test suite does, so that they keep
// working and every past finding stays fixed).
//
// An input the library refuses with its one-line errors (ImportError, UserError) is a pass; any
// other exception, a crash or a sanitizer report is a finding.
#pragma once

#include <hlr/kernel/errors.hpp>
#include <hlr/kernel/scene.hpp>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace hlr::fuzz {

template <class Body>
int refused_or_done(Body&& body) {
  try {
    body();
  } catch (const ImportError&) {
  } catch (const UserError&) {
  } catch (const std::exception& e) {
    std::fprintf(stderr, "finding: unexpected exception: %s\n", e.what());
    std::abort();
  }
  return 0;
}

}  // namespace hlr::fuzz
