#include "app/cli/BatchRunner.h"

#include <sys/prctl.h>
#include <sys/resource.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QProcess>
#include <QTimer>
#include <cmath>
#include <csignal>
#include <deque>
#include <limits>
#include <memory>

namespace driftlab::cli {
namespace {

/// How the child names itself on its reason line, removed from the item's error.
const QByteArray kChildPrefix = "driftlab-cli batch-item: ";

struct Child {
    std::size_t index = 0;
    QProcess* process = nullptr;  ///< owned by the loop's parent object, deleted later
    QElapsedTimer clock;
    bool timedOut = false;
    QString startError;  ///< set when the child could not be started at all
};

QJsonObject line(const BatchItem& item, bool ok, double seconds) {
    return {{QStringLiteral("item"), item.item},
            {QStringLiteral("ok"), ok},
            {QStringLiteral("seconds"), std::round(seconds * 1000) / 1000}};
}

/// The child's result merged into the item's line, or the reason it gave none.
QJsonObject outcome(const BatchItem& item, const Child& child, const BatchRunOptions& options) {
    QProcess& p = *child.process;
    const double seconds = child.clock.nsecsElapsed() * 1e-9;
    const QByteArray err = p.readAllStandardError();
    const QByteArray out = p.readAllStandardOutput().trimmed();
    QJsonObject json = line(item, false, seconds);
    QJsonArray warnings;
    QByteArray lastLine;
    for (const QByteArray& l : err.split('\n')) {
        const QByteArray trimmed = l.trimmed();
        if (trimmed.startsWith("warning: ")) warnings << QString::fromUtf8(trimmed.mid(9));
        if (!trimmed.isEmpty()) lastLine = trimmed;
    }
    if (lastLine.startsWith(kChildPrefix)) lastLine.remove(0, kChildPrefix.size());
    if (!warnings.isEmpty()) json[QStringLiteral("warnings")] = warnings;

    QString error;
    if (!child.startError.isEmpty())
        error = QStringLiteral("cannot start %1: %2")
                    .arg(QCoreApplication::applicationFilePath(), child.startError);
    else if (child.timedOut)
        error = QStringLiteral("stopped after %1 s (--timeout-s)").arg(options.timeout_s);
    else if (p.exitStatus() == QProcess::CrashExit)
        // Killed by a signal: a crash, or the kernel's OOM killer (SIGKILL).
        error = QStringLiteral("the analysis crashed (signal %1%2)")
                    .arg(p.exitCode())
                    .arg(p.exitCode() == SIGKILL ? QStringLiteral(", killed: out of memory?")
                                                 : QString());
    if (!error.isEmpty()) {
        json[QStringLiteral("error")] = error;
        return json;
    }
    QJsonParseError parseError;
    const QJsonDocument result = QJsonDocument::fromJson(out, &parseError);
    if (result.isObject()) {
        const QJsonObject r = result.object();
        for (auto it = r.begin(); it != r.end(); ++it) json[it.key()] = it.value();
    }
    const bool ok =
        p.exitCode() == 0 && result.isObject() && !json.contains(QStringLiteral("error"));
    json[QStringLiteral("ok")] = ok;
    if (!ok && !json.contains(QStringLiteral("error")))
        json[QStringLiteral("error")] =
            lastLine.isEmpty()
                ? QStringLiteral("the analysis ended with exit code %1 and no reason")
                      .arg(p.exitCode())
                : QString::fromUtf8(lastLine);
    return json;
}

}  // namespace

void runBatch(const std::vector<BatchItem>& items, const BatchRunOptions& options,
              const ItemFinished& finished) {
    std::deque<std::size_t> waiting;
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (items[i].error.isEmpty())
            waiting.push_back(i);
        else
            finished(i, [&] {
                QJsonObject json = line(items[i], false, 0);
                json[QStringLiteral("error")] = items[i].error;
                return json;
            }());
    }
    if (waiting.empty()) return;

    QEventLoop loop;
    QObject owner;  // parents the processes, so that none outlives the batch
    int running = 0;
    const int timeoutMs =
        int(std::min(options.timeout_s * 1000, double(std::numeric_limits<int>::max())));
    const std::optional<double> memoryMb = options.memory_mb;

    std::function<void()> startNext = [&] {
        while (running < options.jobs && !waiting.empty()) {
            auto child = std::make_shared<Child>();
            child->index = waiting.front();
            waiting.pop_front();
            child->process = new QProcess(&owner);
            QProcess* p = child->process;
            p->setChildProcessModifier([memoryMb] {
                // In the child, between fork and exec: it dies with the batch
                // (Ctrl-C, kill) instead of running on as an orphan …
                ::prctl(PR_SET_PDEATHSIG, SIGKILL);
                // … and, when asked, cannot grow past its memory share.
                if (memoryMb) {
                    const rlim_t bytes = rlim_t(*memoryMb * 1024 * 1024);
                    const rlimit limit{bytes, bytes};
                    ::setrlimit(RLIMIT_AS, &limit);
                }
            });
            auto done = [&, child] {
                if (!child->process) return;  // errorOccurred and finished both came
                finished(child->index, outcome(items[child->index], *child, options));
                child->process->deleteLater();
                child->process = nullptr;
                --running;
                startNext();
                if (running == 0 && waiting.empty()) loop.quit();
            };
            QObject::connect(p, &QProcess::finished, &owner, done);
            QObject::connect(p, &QProcess::errorOccurred, &owner,
                             [done, child](QProcess::ProcessError e) {
                                 // A child that never started sends no finished().
                                 if (e != QProcess::FailedToStart || !child->process) return;
                                 child->startError = child->process->errorString();
                                 done();
                             });
            QTimer::singleShot(timeoutMs, p, [child] {
                if (!child->process) return;
                child->timedOut = true;
                child->process->kill();
            });
            ++running;
            child->clock.start();
            p->start(QCoreApplication::applicationFilePath(),
                     QStringList{QStringLiteral("batch-item")}
                         << options.itemArguments << batchItemSource(items[child->index]));
        }
    };
    startNext();
    if (running > 0) loop.exec();
}

}  // namespace driftlab::cli
