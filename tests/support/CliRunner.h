#pragma once
// Runs driftlab-cli (or driftlab-bench) as a user does: a real process, its exit code, stdout and
// stderr.
#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QStringList>
#include <QTemporaryDir>
#include <map>

namespace driftlab::test {

struct CliResult {
    int exitCode = -1;
    QByteArray out;
    QByteArray err;
};

/// Runs `program` with `args` to its end (at most 5 min); `wrapper`, when
/// given, runs it (e.g. setpriv … to run it as another user).
inline CliResult runProgram(const QString& program, const QStringList& args,
                            const QStringList& wrapper = {}) {
    QProcess p;
    if (wrapper.isEmpty())
        p.start(program, args);
    else
        p.start(wrapper.front(), wrapper.mid(1) << program << args);
    EXPECT_TRUE(p.waitForFinished(300'000))
        << qPrintable(program) << " " << qPrintable(args.join(' '));
    return {p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1, p.readAllStandardOutput(),
            p.readAllStandardError()};
}

/// Runs a real tool (python3, zip) in `workDir`; fails the test if it fails.
inline void runTool(const QString& program, const QStringList& args, const QString& workDir = {}) {
    QProcess p;
    if (!workDir.isEmpty()) p.setWorkingDirectory(workDir);
    p.start(program, args);
    ASSERT_TRUE(p.waitForFinished(60'000)) << qPrintable(program);
    ASSERT_EQ(p.exitCode(), 0) << qPrintable(program) << ": "
                               << p.readAllStandardError().constData();
}

enum class PdfText {
    Layout,        ///< `pdftotext -layout`: columns and tables as printed
    ReadingOrder,  ///< `pdftotext`, whitespace collapsed: phrases across lines
};

/// The text of a PDF as poppler's pdftotext reads it: the PDF a user opens.
inline QString pdfText(const QString& pdf, PdfText how = PdfText::Layout) {
    QProcess p;
    QStringList args{pdf, QStringLiteral("-")};
    if (how == PdfText::Layout) args.prepend(QStringLiteral("-layout"));
    p.start(QStringLiteral("pdftotext"), args);
    EXPECT_TRUE(p.waitForFinished(60'000));
    EXPECT_EQ(p.exitCode(), 0) << p.readAllStandardError().constData();
    const QString text = QString::fromUtf8(p.readAllStandardOutput());
    return how == PdfText::Layout ? text : text.simplified();
}

inline CliResult runCli(const QStringList& args, const QStringList& wrapper = {}) {
    return runProgram(QStringLiteral(DRIFTLAB_CLI), args, wrapper);
}

/// The JSON object a command printed on stdout (empty when it printed none).
inline QJsonObject json(const CliResult& r) {
    return QJsonDocument::fromJson(r.out).object();
}

/// The last line on stderr, where the one-line reason of a failure stands.
inline QByteArray reason(const QByteArray& err) {
    return err.trimmed().split('\n').last();
}

/// A campaign of the simulated rig with `runs` (e.g. "S1,S3") and `seed`,
/// simulated once per test binary and kept until it ends.
inline const QString& simulatedCampaign(const QString& runs, int seed) {
    static QTemporaryDir dir;
    static std::map<QString, QString> made;
    const QString key = runs + QLatin1Char('-') + QString::number(seed);
    auto found = made.find(key);
    if (found != made.end()) return found->second;
    const QString path = dir.filePath(QStringLiteral("campaign-") + key);
    const CliResult r =
        runCli({QStringLiteral("simulate"), QStringLiteral("--out"), path, QStringLiteral("--runs"),
                runs, QStringLiteral("--seed"), QString::number(seed)});
    EXPECT_EQ(r.exitCode, 0) << r.err.constData();
    return made.emplace(key, path).first->second;
}

}  // namespace driftlab::test
