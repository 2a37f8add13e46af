// iso230-2: ISO 230-2 evaluation of positioning readings from a CSV file or
// from a run of a campaign (docs/iso230.md).
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <cmath>

#include "app/cli/CliCommon.h"
#include "app/cli/IsoOptions.h"
#include "app/cli/StandardsOutput.h"
#include "core/bundle/CsvTable.h"
#include "core/domain/MessageText.h"
#include "core/iso/AcceptanceJson.h"
#include "core/iso/Iso230_2.h"
#include "core/iso/PositioningAcceptance.h"
#include "db/AnalysisJson.h"

namespace driftlab::cli {
namespace {

/// target_mm,direction,cycle,deviation_um rows, in any column order; other
/// columns (a bundle's run,time_s) are ignored. Errors name file:line:column.
std::vector<iso::Reading> readCsv(const QString& path) {
    auto file = std::make_unique<QFile>(path);
    if (!file->open(QIODevice::ReadOnly))
        throw CliError(QStringLiteral("%1: cannot open: %2").arg(path, file->errorString()));
    std::vector<iso::Reading> readings;
    try {
        bundle::CsvTable table(std::move(file), path);
        const int target = table.requireColumn(QStringLiteral("target_mm"));
        const int direction = table.requireColumn(QStringLiteral("direction"));
        const int cycle = table.requireColumn(QStringLiteral("cycle"));
        const int deviation = table.requireColumn(QStringLiteral("deviation_um"));
        while (table.next()) {
            const auto d = directionFromText(table.text(direction));
            if (!d)
                table.fail(direction, QStringLiteral("direction must be '+' (positive approach, "
                                                     "↑) or '-' (negative approach, ↓), not %1")
                                          .arg(quotedCell(table.field(direction))));
            const double target_mm = table.number(target);
            if (std::abs(target_mm) > iso::kMaxTarget_mm)
                table.fail(target, QStringLiteral("target %1 mm is beyond any machine's travel "
                                                  "(±%2 mm)")
                                       .arg(numberText(target_mm), numberText(iso::kMaxTarget_mm)));
            const int cycleNumber = table.integer(cycle, 0);  // cycles count from 0
            readings.push_back({target_mm, *d, cycleNumber, table.number(deviation)});
        }
        if (readings.empty())
            throw CliError(path + QStringLiteral(": no readings after the header"));
    } catch (const bundle::BundleException& e) {
        throw CliError(e.error.toString());
    }
    return readings;
}

void printEvaluation(const iso::Evaluation& e, const QString& source) {
    const double k = e.settings.coverage_factor;
    printLine(QStringLiteral("%1 evaluation of %2: %3 targets, %4 cycles")
                  .arg(iso::toString(e.settings.edition), source)
                  .arg(e.targets.size())
                  .arg(e.cycles));
    printLine(QStringLiteral("coverage factor k = %1 (R↑_i = %2·s↑_i, A from x̄ ± %1·s); "
                             "deviation = actual − target, in µm; ↑ = '+' approach, ↓ = '-'")
                  .arg(k)
                  .arg(2 * k));
    printLine(QString());
    printLine(
        QStringLiteral(" target_mm      x̄↑ µm      x̄↓ µm      s↑ µm      s↓ µm       B µm"
                       "      R↑ µm      R↓ µm       R µm"));
    for (const iso::TargetResult& t : e.targets) {
        QString line = QStringLiteral("%1").arg(t.target_mm, 10, 'f', 3);
        for (double v : {t.mean_up_um, t.mean_down_um, t.s_up_um, t.s_down_um, t.reversal_um,
                         t.r_up_um, t.r_down_um, t.r_um})
            line += QStringLiteral("%1").arg(umText(v), 11);
        printLine(line);
    }
    const iso::AxisResult& a = e.axis;
    // Symbols with a combining mark (x̄, B̄) are one column wide but two
    // characters long: the labels are padded by hand, not by QString::arg.
    const std::pair<const char*, double> rows[] = {
        {"B    reversal error (max |B_i|)                  ", a.reversal_um},
        {"B̄    mean reversal error                         ", a.mean_reversal_um},
        {"R↑   unidirectional repeatability ↑              ", a.r_up_um},
        {"R↓   unidirectional repeatability ↓              ", a.r_down_um},
        {"R    bidirectional repeatability                 ", a.r_um},
        {"E↑   unidirectional systematic error ↑           ", a.e_up_um},
        {"E↓   unidirectional systematic error ↓           ", a.e_down_um},
        {"E    bidirectional systematic error              ", a.e_um},
        {"M    mean bidirectional positioning error        ", a.m_um},
        {"A↑   unidirectional accuracy ↑                   ", a.a_up_um},
        {"A↓   unidirectional accuracy ↓                   ", a.a_down_um},
        {"A    bidirectional accuracy                      ", a.a_um}};
    printLine(QString());
    printLine(QStringLiteral("axis (%1, k = %2):").arg(iso::toString(e.settings.edition)).arg(k));
    for (const auto& [label, value] : rows)
        printLine(QStringLiteral("  ") + QString::fromUtf8(label) +
                  QStringLiteral("%1 µm").arg(umText(value), 9));
    for (const QString& why : e.skipped) printLine(QStringLiteral("not determined: ") + why);
}

}  // namespace

int iso230Command(const QStringList& args) {
    QCommandLineParser parser;
    const QCommandLineOption edition = isoEditionOption();
    const QCommandLineOption coverage = isoCoverageOption();
    const QCommandLineOption runOption{
        QStringLiteral("run"),
        QStringLiteral("With a BUNDLE or --db: the run to evaluate (default: the positioning run, "
                       "or the only run with positioning readings)."),
        QStringLiteral("R")};
    const QCommandLineOption specOption = acceptanceSpecOption();
    const QCommandLineOption standardOption{
        QStringLiteral("standard"),
        QStringLiteral("Evaluate by NAME: iso230-2:2014 (default), iso230-2:2006, iso230-2:1997, "
                       "gbt17421.2, jis-b0182; or all, every standard side by side "
                       "(docs/standards.md)."),
        QStringLiteral("NAME")};
    parseArguments(parser, args,
                   campaignSourceOptions()
                       << edition << coverage << runOption << specOption << standardOption,
                   {QStringLiteral("CSV"),
                    QStringLiteral("Readings: a CSV file with columns target_mm, direction (+ "
                                   "or -), cycle, deviation_um (actual - target); or a campaign "
                                   "bundle folder or .zip (its positioning.csv)."),
                    QStringLiteral("CSV (or BUNDLE, or --db FILE --campaign ID)"),
                    {}});
    iso::Settings settings = isoSettings(parser);
    const StandardChoice choice =
        chooseStandard(parser, standardOption, edition, coverage, settings);

    const QStringList positional = parser.positionalArguments();
    std::vector<iso::Reading> readings;
    QString source;
    std::optional<iso::PositioningAcceptance> acceptance;
    const bool fromCsv = !parser.isSet(QStringLiteral("db")) && positional.size() == 1 &&
                         !QFileInfo(positional.front()).isDir() &&
                         !positional.front().endsWith(QLatin1String(".zip"), Qt::CaseInsensitive);
    if (positional.isEmpty() && !parser.isSet(QStringLiteral("db")))
        throw CliError(QStringLiteral("give a CSV file, a BUNDLE or --db FILE --campaign ID"), 2);
    if (fromCsv) {
        if (parser.isSet(runOption))
            throw CliError(QStringLiteral("--run is for a BUNDLE or --db, not a CSV file"), 2);
        if (parser.isSet(specOption))
            throw CliError(QStringLiteral("--spec needs a campaign (BUNDLE or --db): the 20 °C "
                                          "normalisation and the budget read its thermometers; "
                                          "import the CSV first"),
                           2);
        source = positional.front();
        readings = readCsv(source);
    } else {
        if (positional.size() > 1 || (parser.isSet(QStringLiteral("db")) && !positional.isEmpty()))
            throw CliError(QStringLiteral("give one CSV, one BUNDLE or --db FILE --campaign ID"),
                           2);
        const Campaign campaign = loadCampaignSource(parser);
        const Run& run = choosePositioningRun(campaign, parser.value(runOption));
        source = QStringLiteral("run %1 of %2").arg(run.id, campaign.name);
        readings = iso::readingsOf(run);
        if (const auto spec = acceptanceSpecification(parser, campaign)) {
            acceptance = iso::evaluateAcceptance(campaign, run, *spec, settings);
            if (!acceptance->ok())
                throw CliError(source + QStringLiteral(": ") + acceptance->error);
        }
    }

    if (choice.all || choice.standard)
        return evaluateByStandard(choice, acceptance ? acceptance->readings : readings, settings,
                                  source, parser.isSet(QStringLiteral("json")));
    const iso::Evaluation result =
        acceptance ? acceptance->evaluation : iso::evaluate(readings, settings);
    if (!result.ok()) throw CliError(source + QStringLiteral(": ") + result.error);
    printWarnings(result.warnings);
    if (parser.isSet(QStringLiteral("json"))) {
        QJsonObject json = db::iso230EvaluationJson(result);
        json[QStringLiteral("source")] = source;
        if (acceptance) json[QStringLiteral("acceptance")] = iso::acceptanceJson(*acceptance);
        printJson(json);
        return 0;
    }
    printEvaluation(result, source);
    if (acceptance) {
        printLine(QString());
        for (const QString& line : iso::acceptanceText(*acceptance)) printLine(line);
    }
    return 0;
}

}  // namespace driftlab::cli
