// The main of every test executable. A passing test prints nothing: what Qt
// and Ceres (through glog) log while a test runs is kept and printed only
// when that test fails, under its name. With DRIFTLAB_TEST_QAPPLICATION, one
// QApplication for the whole binary (GUI pages, device workers, queued
// signals), offscreen unless told otherwise.
#include <glog/logging.h>
#include <gtest/gtest.h>

#include <QString>
#include <QStringList>
#include <QTemporaryDir>
#include <cstdio>
#include <mutex>

#ifdef DRIFTLAB_TEST_QAPPLICATION
#include <QApplication>
#else
#include <QCoreApplication>
#endif

namespace {

std::mutex g_logMutex;
QStringList g_log;  ///< what was logged during the running test

void keepMessage(QtMsgType, const QMessageLogContext& context, const QString& message) {
    const std::lock_guard lock(g_logMutex);
    g_log << (context.category && qstrcmp(context.category, "default") != 0
                  ? QString::fromLatin1(context.category) + QStringLiteral(": ") + message
                  : message);
}

/// Prints the kept messages of a test that failed, and forgets them.
class KeptLogPrinter : public testing::EmptyTestEventListener {
    void OnTestStart(const testing::TestInfo&) override {
        const std::lock_guard lock(g_logMutex);
        g_log.clear();
    }
    void OnTestEnd(const testing::TestInfo& info) override {
        const std::lock_guard lock(g_logMutex);
        if (info.result()->Failed() && !g_log.isEmpty())
            std::fprintf(stderr, "[ logged   ] %s.%s:\n%s\n", info.test_suite_name(), info.name(),
                         qPrintable(g_log.join(QLatin1Char('\n'))));
        g_log.clear();
    }
};

}  // namespace

int main(int argc, char** argv) {
    // Ceres's glog: only fatal messages, as the executables do.
    FLAGS_minloglevel = google::GLOG_FATAL;
    qInstallMessageHandler(keepMessage);
#ifdef DRIFTLAB_TEST_QAPPLICATION
    // Test discovery runs the binary without the ctest environment.
    if (!qEnvironmentVariableIsSet("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    // Settings and app data in a temporary folder: a test never reads or changes the user's.
    QTemporaryDir home;
    qputenv("XDG_CONFIG_HOME", home.filePath(QStringLiteral("config")).toUtf8());
    qputenv("XDG_DATA_HOME", home.filePath(QStringLiteral("data")).toUtf8());
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("DriftLabTest"));
    QApplication::setApplicationName(QStringLiteral("DriftLabTest"));
#endif
    ::testing::InitGoogleTest(&argc, argv);
    testing::UnitTest::GetInstance()->listeners().Append(new KeptLogPrinter);
    return RUN_ALL_TESTS();
}
