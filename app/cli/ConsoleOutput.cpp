#include "app/cli/ConsoleOutput.h"

#include <sys/stat.h>
#include <unistd.h>
#include <QJsonDocument>
#include <cstdio>

namespace driftlab::cli {

namespace {
bool g_progressLineOpen = false;
QString g_progressShown;  ///< "label: percent" last written, to rewrite only on change
}  // namespace

bool printProgress(const QString& label, double fraction) {
    const int percent = int(fraction * 100 + 0.5);
    // On a terminal the line is rewritten in place; in a log (CI, a script's
    // stderr) it grows by tens of per cent so the log stays readable.
    static const bool terminal = isatty(fileno(stderr));
    const int shownPercent = terminal ? percent : percent / 10 * 10;
    const QString shown = QStringLiteral("%1: %2%").arg(label).arg(shownPercent, 3);
    if (shown == g_progressShown) return true;
    const bool sameLabel = g_progressShown.startsWith(label + QLatin1Char(':'));
    g_progressShown = shown;
    if (terminal)
        std::fprintf(stderr, "\r%s", qPrintable(shown));
    else if (sameLabel && g_progressLineOpen)
        std::fprintf(stderr, " %d%%", shownPercent);
    else
        std::fprintf(stderr, "%s%s", g_progressLineOpen ? "\n" : "", qPrintable(shown));
    g_progressLineOpen = fraction < 1.0;
    if (!g_progressLineOpen) std::fputc('\n', stderr);
    return true;
}

void endProgressLine() {
    if (g_progressLineOpen) std::fputc('\n', stderr);
    g_progressLineOpen = false;
}

void prepareHeadlessQt() {
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM")) qputenv("QT_QPA_PLATFORM", "offscreen");
    if (qEnvironmentVariableIsEmpty("XDG_RUNTIME_DIR")) {
        const QByteArray runtime = QByteArray("/tmp/runtime-") + QByteArray::number(getuid());
        mkdir(runtime.constData(), 0700);
        qputenv("XDG_RUNTIME_DIR", runtime);
    }
}

void printJson(const QJsonObject& object) {
    std::fputs(QJsonDocument(object).toJson(QJsonDocument::Compact).constData(), stdout);
    std::fputc('\n', stdout);
}

void printLine(const QString& text) {
    std::fputs(text.toUtf8().constData(), stdout);
    std::fputc('\n', stdout);
}

}  // namespace driftlab::cli
