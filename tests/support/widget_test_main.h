#pragma once
// A widget test's main: QTEST_MAIN's, with the fonts the tests measure with (test_fonts.h)
// loaded before the test object, and so before any widget, is made.
#include <QApplication>
#include <QTest>

#include "tests/support/test_fonts.h"

#define TRILHO_WIDGET_TEST_MAIN(TestObject)                             \
    int main(int argc, char* argv[]) {                                  \
        QApplication app(argc, argv);                                   \
        app.setAttribute(Qt::AA_Use96Dpi, true);                        \
        QTEST_DISABLE_KEYPAD_NAVIGATION                                 \
        trilho::testing::useFontsOrDie(trilho::testing::dejaVuFonts()); \
        TestObject tc;                                                  \
        QTEST_SET_MAIN_SOURCE_PATH                                      \
        return QTest::qExec(&tc, argc, argv);                           \
    }
