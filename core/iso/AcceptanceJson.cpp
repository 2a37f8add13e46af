#include "core/iso/AcceptanceJson.h"

#include <QJsonArray>
#include <cmath>

namespace driftlab::iso {

namespace {

QJsonValue number(double value) {
    return std::isfinite(value) ? QJsonValue(value) : QJsonValue(QJsonValue::Null);
}

QJsonValue temperatureJson(const std::optional<TemperatureSummary>& t) {
    if (!t) return QJsonValue::Null;
    return QJsonObject{{QStringLiteral("channels"), QJsonArray::fromStringList(t->channels)},
                       {QStringLiteral("start_C"), t->start_C},
                       {QStringLiteral("end_C"), t->end_C},
                       {QStringLiteral("min_C"), t->min_C},
                       {QStringLiteral("max_C"), t->max_C},
                       {QStringLiteral("mean_C"), t->mean_C},
                       {QStringLiteral("samples"), t->samples}};
}

QString modeText(Normalisation::Mode mode) {
    switch (mode) {
        case Normalisation::Mode::Normalised:
            return QStringLiteral("normalised");
        case Normalisation::Mode::MachineCompensates:
            return QStringLiteral("machine-compensates");
        case Normalisation::Mode::NotNormalised:
            return QStringLiteral("not-normalised");
    }
    return {};
}

QString temperatureLine(const char* what, const std::optional<TemperatureSummary>& t) {
    if (!t) return QStringLiteral("  %1: not logged").arg(QLatin1String(what));
    return QStringLiteral("  %1 (%2): start %3, end %4, min %5, max %6, mean %7 °C")
        .arg(QLatin1String(what), t->channels.join(QStringLiteral(", ")))
        .arg(t->start_C, 0, 'f', 2)
        .arg(t->end_C, 0, 'f', 2)
        .arg(t->min_C, 0, 'f', 2)
        .arg(t->max_C, 0, 'f', 2)
        .arg(t->mean_C, 0, 'f', 2);
}

}  // namespace

QString decisionRuleText() {
    return QStringLiteral(
        "ISO 14253-1: PASS when value + U ≤ tolerance, FAIL when value − U > "
        "tolerance, otherwise NOT PROVEN");
}

QJsonArray decisionsJson(const std::vector<Decision>& decisions) {
    QJsonArray array;
    for (const Decision& d : decisions)
        array.append(QJsonObject{{QStringLiteral("parameter"), d.parameter},
                                 {QStringLiteral("value_um"), number(d.value_um)},
                                 {QStringLiteral("expanded_uncertainty_um"), d.expanded_um},
                                 {QStringLiteral("tolerance_um"), d.tolerance_um},
                                 {QStringLiteral("margin_um"), number(d.margin_um)},
                                 {QStringLiteral("verdict"), toString(d.verdict)}});
    return array;
}

QStringList decisionsText(const std::vector<Decision>& decisions) {
    QStringList lines{
        QStringLiteral("  value         result µm      U µm  tolerance µm   margin µm  "
                       "verdict")};
    for (const Decision& d : decisions)
        lines << QStringLiteral("  %1 %2 %3 %4 %5  %6")
                     .arg(d.parameter, -11)
                     .arg(d.value_um, 12, 'f', 3)
                     .arg(d.expanded_um, 9, 'f', 3)
                     .arg(d.tolerance_um, 13, 'f', 3)
                     .arg(d.margin_um, 11, 'f', 3)
                     .arg(toString(d.verdict));
    return lines;
}

QJsonObject acceptanceJson(const PositioningAcceptance& a) {
    QJsonArray contributions;
    for (const UncertaintyContribution& c : a.budget.contributions)
        contributions.append(QJsonObject{{QStringLiteral("key"), c.key},
                                         {QStringLiteral("name"), c.name},
                                         {QStringLiteral("equation"), c.equation},
                                         {QStringLiteral("standard_um"), c.standard_um},
                                         {QStringLiteral("length_dependent"), c.length_dependent}});
    QJsonObject parameters;
    for (const ParameterUncertainty& p : a.budget.parameters)
        parameters[p.parameter] = QJsonObject{
            {QStringLiteral("contributors"), QJsonArray::fromStringList(p.contributors)},
            {QStringLiteral("combined_um"), p.combined_um},
            {QStringLiteral("expanded_um"), p.expanded_um}};
    const UncertaintyConditions& c = a.budget.conditions;
    return {
        {QStringLiteral("run"), a.run_id},
        {QStringLiteral("axis"), a.axis},
        {QStringLiteral("environment"),
         QJsonObject{{QStringLiteral("start_s"), a.environment.start_s},
                     {QStringLiteral("end_s"), a.environment.end_s},
                     {QStringLiteral("air"), temperatureJson(a.environment.air)},
                     {QStringLiteral("material"), temperatureJson(a.environment.material)},
                     {QStringLiteral("notes"), QJsonArray::fromStringList(a.environment.notes)}}},
        {QStringLiteral("normalisation"),
         QJsonObject{
             {QStringLiteral("mode"), modeText(a.normalisation.mode)},
             {QStringLiteral("expansion_per_K"), c.expansion_per_K},
             {QStringLiteral("material_temperature_C"), c.material_temperature_C},
             {QStringLiteral("largest_correction_um"), a.normalisation.largest_correction_um},
             {QStringLiteral("description"), a.normalisation.description}}},
        {QStringLiteral("uncertainty"),
         QJsonObject{{QStringLiteral("coverage_factor"), a.budget.coverage_k},
                     {QStringLiteral("length_mm"), c.length_mm},
                     {QStringLiteral("eve_um"), c.eve_um},
                     {QStringLiteral("eve_source"), c.eve_source},
                     {QStringLiteral("contributions"), contributions},
                     {QStringLiteral("parameters"), parameters},
                     {QStringLiteral("notes"), QJsonArray::fromStringList(a.budget.notes)}}},
        {QStringLiteral("decision_rule"), decisionRuleText()},
        {QStringLiteral("verdict"), toString(a.overall())},
        {QStringLiteral("decisions"), decisionsJson(a.decisions)},
        {QStringLiteral("notes"), QJsonArray::fromStringList(a.notes)}};
}

QStringList acceptanceText(const PositioningAcceptance& a) {
    QStringList lines;
    lines << QStringLiteral("environment during the test (%1 s to %2 s):")
                 .arg(a.environment.start_s, 0, 'f', 0)
                 .arg(a.environment.end_s, 0, 'f', 0);
    lines << temperatureLine("air", a.environment.air)
          << temperatureLine("material", a.environment.material);
    for (const QString& note : a.environment.notes) lines << QStringLiteral("  note: ") + note;
    lines << QStringLiteral("temperature: ") + a.normalisation.description;
    lines << QString();
    lines << QStringLiteral("uncertainty budget over %1 mm (standard uncertainties):")
                 .arg(a.budget.conditions.length_mm, 0, 'f', 1);
    for (const UncertaintyContribution& c : a.budget.contributions)
        lines << QStringLiteral("  %1 %2  %3")
                     .arg(c.name, -66)
                     .arg(QString::number(c.standard_um, 'f', 3), 8)
                     .arg(c.equation);
    lines << QStringLiteral("  expanded uncertainty U (k = %1):").arg(a.budget.coverage_k);
    QString row;
    for (const ParameterUncertainty& p : a.budget.parameters)
        row += QStringLiteral("  %1 %2").arg(p.parameter).arg(p.expanded_um, 0, 'f', 2);
    lines << QStringLiteral("   ") + row + QStringLiteral("  µm");
    for (const QString& note : a.budget.notes) lines << QStringLiteral("  note: ") + note;
    if (!a.decisions.empty()) {
        lines << QString();
        lines << QStringLiteral(
                     "acceptance by ISO 14253-1 (conformance proven when value + U ≤ "
                     "tolerance): %1")
                     .arg(toString(a.overall()));
        lines << decisionsText(a.decisions);
    }
    for (const QString& note : a.notes) lines << QStringLiteral("note: ") + note;
    return lines;
}

}  // namespace driftlab::iso
