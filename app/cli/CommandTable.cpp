#include "app/cli/CommandTable.h"

#include <algorithm>

namespace driftlab::cli {

int importCommand(const QStringList& args);
int exportCommand(const QStringList& args);
int infoCommand(const QStringList& args);
int simulateCommand(const QStringList& args);
int fitCommand(const QStringList& args);
int compareCommand(const QStringList& args);
int diagnoseCommand(const QStringList& args);
int iso230Command(const QStringList& args);
int iso230_3Command(const QStringList& args);
int historyCommand(const QStringList& args);
int compensateCommand(const QStringList& args);
int liveCommand(const QStringList& args);
int healthCommand(const QStringList& args);
int controllerSimCommand(const QStringList& args);
int pushesCommand(const QStringList& args);
int runCommand(const QStringList& args);
int reportCommand(const QStringList& args);
int batchCommand(const QStringList& args);
int batchItemCommand(const QStringList& args);
int syncCommand(const QStringList& args);

namespace {

/// Levenshtein distance: how many letters to insert, delete or change.
int editDistance(const QString& a, const QString& b) {
    std::vector<int> previous(b.size() + 1), current(b.size() + 1);
    for (int j = 0; j <= b.size(); ++j) previous[j] = j;
    for (int i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (int j = 1; j <= b.size(); ++j)
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1,
                                   previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
        std::swap(previous, current);
    }
    return previous[b.size()];
}

/// `text` in lines of at most `width` characters, each indented by `indent`.
QString wrapped(const QString& text, int indent, int width) {
    QString out, line;
    const QString margin(indent, QLatin1Char(' '));
    for (const QString& word : text.split(QLatin1Char(' '), Qt::SkipEmptyParts)) {
        if (!line.isEmpty() && indent + line.size() + 1 + word.size() > width) {
            out += margin + line + QLatin1Char('\n');
            line.clear();
        }
        line += (line.isEmpty() ? QString() : QStringLiteral(" ")) + word;
    }
    if (!line.isEmpty()) out += margin + line + QLatin1Char('\n');
    return out;
}

}  // namespace

const std::vector<Command>& commands() {
    static const std::vector<Command> table{
        {QStringLiteral("import"), importCommand, QStringLiteral("import BUNDLE --db FILE"),
         QStringLiteral("Store a campaign bundle in the database (one transaction); "
                        "prints the campaign id.")},
        {QStringLiteral("export"), exportCommand,
         QStringLiteral("export --db FILE --campaign ID --out DIR"),
         QStringLiteral("Write a campaign of the database back as a bundle, lossless.")},
        {QStringLiteral("info"), infoCommand, QStringLiteral("info BUNDLE"),
         QStringLiteral("Runs, channels, sample and measurement counts of a campaign.")},
        {QStringLiteral("simulate"), simulateCommand,
         QStringLiteral("simulate --out DIR [--effect ID=VALUE]... [--seed N]"),
         QStringLiteral("A campaign from the simulated rig, five moving states by default.")},
        {QStringLiteral("fit"), fitCommand,
         QStringLiteral("fit BUNDLE --model NAME [--train R,..] [--test R,..] [--target CH]"),
         QStringLiteral("Fit one thermal-error model and score it on held-out runs.")},
        {QStringLiteral("compare"), compareCommand, QStringLiteral("compare BUNDLE"),
         QStringLiteral("Every model, as a cross-state matrix (fitted on one run, scored on "
                        "each).")},
        {QStringLiteral("diagnose"), diagnoseCommand,
         QStringLiteral("diagnose BUNDLE [--train R,.. --test R,..]"),
         QStringLiteral("What the physical model misses, the likely cause and the gain of "
                        "modelling it.")},
        {QStringLiteral("iso230-2"), iso230Command,
         QStringLiteral("iso230-2 CSV [--edition 2014|2006|1997] [--standard NAME|all] [--run R]"),
         QStringLiteral("ISO 230-2 evaluation of target_mm,direction,cycle,deviation_um rows "
                        "(a CSV file, or a run of a campaign): accuracy, repeatability, "
                        "reversal per target and for the axis.")},
        {QStringLiteral("iso230-3"), iso230_3Command,
         QStringLiteral("iso230-3 BUNDLE [--run R] [--window-s W] [--tolerance-um D]"),
         QStringLiteral("ISO 230-3 thermal drift: per target of a moving run, per probe of a "
                        "spindle or ETVE run, the maximum drift, when, and when it stabilised.")},
        {QStringLiteral("history"), historyCommand,
         QStringLiteral("history --db FILE --machine M --axis X [--png FILE]"),
         QStringLiteral("Every campaign of one machine axis in a store, oldest first: its ISO "
                        "230-2 figures (A, E, R, B, M), ISO 230-3 drift and their change.")},
        {QStringLiteral("compensate"), compensateCommand,
         QStringLiteral("compensate BUNDLE --format F --out FILE | --push modbus://HOST:PORT "
                        "[--spacing MM | --points N] [--bidirectional]"),
         QStringLiteral("A pitch-error compensation table from a run's positioning readings, "
                        "written for a controller (linuxcnc, linuxcnc-type1, fanuc, fanuc-g10, "
                        "sinumerik, heidenhain, csv) and/or pushed to it over Modbus TCP.")},
        {QStringLiteral("pushes"), pushesCommand,
         QStringLiteral("pushes --db FILE [--campaign ID]"),
         QStringLiteral("The compensation push history of a store: when, which table, which "
                        "controller, what happened.")},
        {QStringLiteral("controller-sim"), controllerSimCommand,
         QStringLiteral("controller-sim [--port N] [--state S] [--axis P,F,T] [--fault F]..."),
         QStringLiteral("Serve the simulated controller of DriftLab's Modbus register map until "
                        "Ctrl-C (for trying the push and the map).")},
        {QStringLiteral("live"), liveCommand,
         QStringLiteral("live BUNDLE --run R --train R,.. [--model M] [--interval-s S] "
                        "[--cutting FROM-TO,..]"),
         QStringLiteral("Live thermal compensation replayed on a measured run: the heat-transfer "
                        "model (or an adopted extension) fitted on the training runs updates the "
                        "correction online, only between cuts, and is scored on the run's "
                        "measured thermal error.")},
        {QStringLiteral("health"), healthCommand,
         QStringLiteral("health BUNDLE [--run R,..] [--redundant A=B]... [--store]"),
         QStringLiteral("Sensor self-diagnosis of the logged samples: out of range (open, short), "
                        "frozen, spikes, rate of change, drift between redundant sensors; per "
                        "run and channel, how many samples and when.")},
        {QStringLiteral("run"), runCommand,
         QStringLiteral("run --procedure FILE --rig sim|modbus://HOST:PORT --db FILE|URL "
                        "[--spool FILE] [--speedup N] [--resume RUN]"),
         QStringLiteral("Run a test procedure (ISO 230-2, ISO 230-3, ETVE, spindle, moving "
                        "states) on a rig and log it live into the store; prints the campaign "
                        "id. Ctrl-C keeps what was logged; --resume continues the run. With a "
                        "postgresql:// --db it logs into a local spool and uploads it.")},
        {QStringLiteral("sync"), syncCommand, QStringLiteral("sync --db URL [--spool FILE]"),
         QStringLiteral("Upload what a rig's spool holds and the server store does not: runs "
                        "logged while the server was away (docs/lab-store.md).")},
        {QStringLiteral("report"), reportCommand,
         QStringLiteral("report BUNDLE --pdf FILE | --html DIR | --csv DIR [--run R] "
                        "[--operator NAME]"),
         QStringLiteral("The acceptance report: ISO 230-2, ISO 230-3, model comparison, "
                        "diagnosis and compensation, as PDF (vector plots), HTML and/or CSV.")},
        {QStringLiteral("batch"), batchCommand,
         QStringLiteral("batch PATH... [-j N] [--what info,iso230-2,fit,diagnose] "
                        "[--timeout-s S]"),
         QStringLiteral("Analyse many bundles or databases, one JSON line each: bundle folders, "
                        ".zip bundles, stores (each campaign in them) and folders searched for "
                        "them, N at a time in separate processes.")},
        {QStringLiteral("batch-item"), batchItemCommand,
         QStringLiteral("batch-item BUNDLE [--what LIST]"),
         QStringLiteral("One item of batch, analysed in the child process batch starts for it."),
         true},
    };
    return table;
}

const Command* findCommand(const QString& name) {
    for (const Command& command : commands())
        if (command.name == name) return &command;
    return nullptr;
}

QString closestCommand(const QString& name) {
    // A unique prefix ("diag") is what was meant; so is a name one or two
    // typos away, as long as the typos do not make up most of the word.
    QStringList prefixed;
    for (const Command& command : commands())
        if (!command.hidden && name.size() >= 2 && command.name.startsWith(name))
            prefixed << command.name;
    if (prefixed.size() == 1) return prefixed.front();
    QString best;
    int bestDistance = std::min<int>(2, (name.size() - 1) / 2) + 1;
    for (const Command& command : commands()) {
        if (command.hidden) continue;
        const int d = editDistance(name.toLower(), command.name);
        if (d < bestDistance) {
            bestDistance = d;
            best = command.name;
        }
    }
    return best;
}

QString notBuiltReason() {
    return QStringLiteral("not built yet in DriftLab %1").arg(QStringLiteral(DRIFTLAB_VERSION));
}

QString usageText() {
    QString text = QStringLiteral(
        "Usage: driftlab-cli COMMAND [options]\n"
        "       driftlab-cli help COMMAND    the options of COMMAND (or COMMAND --help)\n"
        "       driftlab-cli --version\n"
        "\n"
        "Commands:\n");
    // The synopsis on its own line, what it does below it: synopses are too
    // long for two columns in a terminal of 80.
    for (const Command& command : commands()) {
        if (command.hidden) continue;
        text += QStringLiteral("  %1%2\n")
                    .arg(command.synopsis,
                         command.run ? QString() : QStringLiteral("   (not built yet)")) +
                wrapped(command.summary, 6, 79);
    }
    text += QStringLiteral(
        "\n"
        "Wherever a BUNDLE is taken, --db FILE --campaign ID may be given instead.\n"
        "Progress goes to stderr, results to stdout (--json for scripts).\n"
        "Exit codes: 0 done, 1 failed (last stderr line says why), 2 usage error,\n"
        "            3 run aborted with Ctrl-C (the run is kept, interrupted).\n");
    return text;
}

}  // namespace driftlab::cli
