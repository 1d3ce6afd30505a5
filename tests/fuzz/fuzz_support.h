#pragma once
// What every fuzz target shares: a QCoreApplication (translators need one) made once, and a
// check that stops the run with a message, so a broken invariant is a finding like a crash.
#include <QCoreApplication>
#include <cstdio>
#include <cstdlib>

namespace trilho::fuzz {

inline void ensureApplication() {
    static int argc = 1;
    static char name[] = "trilho-fuzz";
    static char* argv[] = {name, nullptr};
    static QCoreApplication* app =
        QCoreApplication::instance() ? nullptr : new QCoreApplication(argc, argv);
    (void)app;
}

[[noreturn]] inline void violated(const char* what, const char* file, int line) {
    std::fprintf(stderr, "%s:%d: invariant violated: %s\n", file, line, what);
    std::abort();
}

}  // namespace trilho::fuzz

#define FUZZ_CHECK(cond) \
    ((cond) ? static_cast<void>(0) : ::trilho::fuzz::violated(#cond, __FILE__, __LINE__))
