#include "app/cli/StandardsOutput.h"

#include <QJsonArray>
#include <algorithm>
#include <vector>

#include "app/cli/CliCommon.h"
#include "app/cli/ConsoleOutput.h"

namespace driftlab::cli {
namespace {

/// Columns a text takes on a terminal: a combining mark (the bar of x̄, B̄)
/// sits on the character before it.
int displayWidth(const QString& text) {
    int width = 0;
    for (const QChar c : text)
        if (!c.isMark()) ++width;
    return width;
}

QString padRight(const QString& text, int width) {
    return text + QString(std::max(0, width - displayWidth(text)), QLatin1Char(' '));
}

QString padLeft(const QString& text, int width) {
    return QString(std::max(0, width - displayWidth(text)), QLatin1Char(' ')) + text;
}

QString countsText(const iso::StandardEvaluation& e) {
    return QStringLiteral("%1 targets, %2 cycles").arg(e.targets).arg(e.cycles);
}

QString approachesText(const iso::StandardEvaluation& e) {
    return e.min_approaches > 0
               ? QStringLiteral("%1 approaches per direction and target").arg(e.min_approaches)
               : QStringLiteral("no minimum of approaches stated");
}

constexpr int kSymbolWidth = 5;
constexpr int kMeaningWidth = 42;

}  // namespace

QJsonObject standardEvaluationJson(const iso::StandardEvaluation& e) {
    QJsonObject values;
    for (const iso::StandardValue& v : e.values) values[v.key] = jsonNumber(v.value_um);
    return {{QStringLiteral("id"), iso::standardId(e.standard)},
            {QStringLiteral("standard"), iso::standardTitle(e.standard)},
            {QStringLiteral("coverage_factor"), e.coverage_factor},
            {QStringLiteral("min_approaches"), e.min_approaches},
            {QStringLiteral("definitions"), e.definitions},
            {QStringLiteral("unit"), QStringLiteral("µm")},
            {QStringLiteral("values"), values},
            {QStringLiteral("targets"), e.targets},
            {QStringLiteral("cycles"), e.cycles},
            {QStringLiteral("skipped"), QJsonArray::fromStringList(e.skipped)},
            {QStringLiteral("warnings"), QJsonArray::fromStringList(e.warnings)}};
}

QJsonObject standardsComparisonJson(const iso::StandardsComparison& c) {
    QJsonArray standards, notEvaluated;
    for (const iso::StandardEvaluation& e : c.evaluations)
        standards.append(standardEvaluationJson(e));
    for (const iso::LeftOutStandard& s : iso::leftOutStandards())
        notEvaluated.append(QJsonObject{{QStringLiteral("id"), s.id},
                                        {QStringLiteral("standard"), s.title},
                                        {QStringLiteral("why"), s.why}});
    return {{QStringLiteral("unit"), QStringLiteral("µm")},
            {QStringLiteral("standards"), standards},
            {QStringLiteral("not_evaluated"), notEvaluated},
            {QStringLiteral("warnings"), QJsonArray::fromStringList(c.warnings)}};
}

void printStandardEvaluation(const iso::StandardEvaluation& e, const QString& source) {
    const QString title = iso::standardTitle(e.standard);
    printLine(QStringLiteral("%1 evaluation of %2: %3").arg(title, source, countsText(e)));
    printLine(e.definitions + QStringLiteral("; ") + approachesText(e));
    printLine(QStringLiteral("deviation = actual − target, in µm; ↑ = '+' approach, ↓ = '-'"));
    printLine(QString());
    printLine(QStringLiteral("axis (%1, k = %2):").arg(title).arg(e.coverage_factor));
    for (const iso::StandardValue& v : e.values)
        printLine(QStringLiteral("  ") + padRight(v.symbol, kSymbolWidth) +
                  padRight(v.meaning, kMeaningWidth) +
                  QStringLiteral("%1 µm").arg(umText(v.value_um), 9));
    for (const QString& why : e.skipped) printLine(QStringLiteral("not determined: ") + why);
}

void printStandardsComparison(const iso::StandardsComparison& c, const QString& source) {
    if (c.evaluations.empty()) return;
    printLine(QStringLiteral("Positioning standards compared on %1: %2")
                  .arg(source, countsText(c.evaluations.front())));
    printLine(
        QStringLiteral("values in µm; n/a = not determined, - = not defined by the standard"));
    printLine(QString());
    std::vector<int> widths;
    QString header = QString(2 + kSymbolWidth + kMeaningWidth, QLatin1Char(' '));
    for (const iso::StandardEvaluation& e : c.evaluations) {
        const QString title = iso::standardTitle(e.standard);
        widths.push_back(std::max(displayWidth(title), 9) + 2);
        header += padLeft(title, widths.back());
    }
    printLine(header);
    for (const iso::StandardValue* row : iso::comparisonRows(c)) {
        QString line = QStringLiteral("  ") + padRight(row->symbol, kSymbolWidth) +
                       padRight(row->meaning, kMeaningWidth);
        for (std::size_t i = 0; i < c.evaluations.size(); ++i) {
            const iso::StandardValue* v = c.evaluations[i].value(row->key);
            line += padLeft(v ? umText(v->value_um) : QStringLiteral("-"), widths[i]);
        }
        printLine(line);
    }
    printLine(QString());
    printLine(QStringLiteral("coverage and definitions:"));
    int titleWidth = 0;
    for (const iso::StandardEvaluation& e : c.evaluations)
        titleWidth = std::max(titleWidth, displayWidth(iso::standardTitle(e.standard)));
    for (const iso::StandardEvaluation& e : c.evaluations) {
        printLine(QStringLiteral("  ") + padRight(iso::standardTitle(e.standard), titleWidth + 2) +
                  e.definitions + QStringLiteral("; ") + approachesText(e));
        for (const QString& why : e.skipped)
            printLine(QStringLiteral("  ") + QString(titleWidth + 2, QLatin1Char(' ')) +
                      QStringLiteral("not determined: ") + why);
    }
    printLine(QString());
    printLine(QStringLiteral("not evaluated (docs/standards.md):"));
    for (const iso::LeftOutStandard& s : iso::leftOutStandards())
        printLine(QStringLiteral("  ") + padRight(s.title, titleWidth + 2) + s.why);
}

StandardChoice chooseStandard(const QCommandLineParser& parser, const QCommandLineOption& option,
                              const QCommandLineOption& edition, const QCommandLineOption& coverage,
                              iso::Settings& settings) {
    StandardChoice choice;
    if (!parser.isSet(option)) return choice;
    const QString name = parser.value(option).trimmed();
    if (const iso::LeftOutStandard* left = iso::leftOutStandard(name))
        throw CliError(QStringLiteral("--standard %1: %2 is not evaluated: %3 (docs/standards.md)")
                           .arg(name, left->title, left->why),
                       2);
    choice.all = name.compare(QLatin1String("all"), Qt::CaseInsensitive) == 0;
    if (!choice.all) {
        choice.standard = iso::standardFromId(name);
        if (!choice.standard) {
            QStringList names;
            for (iso::PositioningStandard s : iso::positioningStandards())
                names << iso::standardId(s);
            throw CliError(QStringLiteral("--standard: '%1' is not one of %2 or all")
                               .arg(name, names.join(QStringLiteral(", "))),
                           2);
        }
    }
    const std::optional<iso::Edition> asIso =
        choice.standard ? iso::isoEditionOf(*choice.standard) : std::nullopt;
    if (asIso) {
        if (parser.isSet(edition) && *asIso != settings.edition)
            throw CliError(QStringLiteral("--standard %1 and --edition %2 name different editions")
                               .arg(name, parser.value(edition)),
                           2);
        settings.edition = *asIso;
        choice.standard.reset();  // the ISO 230-2 evaluation, as without --standard
        return choice;
    }
    // Every other standard fixes its own coverage factor and edition.
    for (const QCommandLineOption* o : {&edition, &coverage})
        if (parser.isSet(*o))
            throw CliError(QStringLiteral("--%1 is for ISO 230-2; --standard %2 fixes its own")
                               .arg(o->names().front(), name),
                           2);
    return choice;
}

int evaluateByStandard(const StandardChoice& choice, const std::vector<iso::Reading>& readings,
                       const iso::Settings& settings, const QString& source, bool asJson) {
    QJsonObject json;
    if (choice.all) {
        const iso::StandardsComparison c = iso::compareStandards(readings, settings);
        if (!c.ok()) throw CliError(source + QStringLiteral(": ") + c.error);
        printWarnings(c.warnings);
        if (!asJson) {
            printStandardsComparison(c, source);
            return 0;
        }
        json = standardsComparisonJson(c);
    } else {
        const iso::StandardEvaluation e =
            iso::evaluateStandard(readings, *choice.standard, settings);
        if (!e.ok()) throw CliError(source + QStringLiteral(": ") + e.error);
        printWarnings(e.warnings);
        if (!asJson) {
            printStandardEvaluation(e, source);
            return 0;
        }
        json = standardEvaluationJson(e);
    }
    json[QStringLiteral("source")] = source;
    printJson(json);
    return 0;
}

}  // namespace driftlab::cli
