#include "tests/support/BadBundleCases.h"

#include <QDir>

#include "tests/support/BundleTestSupport.h"

namespace driftlab::test {

void PrintTo(const BadBundleCase& bad, std::ostream* os) {
    *os << bad.name;
}

const std::vector<BadBundleCase>& badBundleCases() {
    auto file = [](const QString& dir, const char* name) {
        return QDir(dir).filePath(QString::fromLatin1(name));
    };
    static const std::vector<BadBundleCase> cases{
        {"wrong_format",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "driftlab.campaign/1", "driftlab.campaign/9");
         },
         "campaign.json", "format: unsupported format 'driftlab.campaign/9'"},
        {"malformed_json",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"name\": \"VMC-850\",",
                           "\"name\": \"VMC-850\",,");
         },
         "campaign.json:5:", ""},
        {"json_with_a_comment",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"name\": \"VMC-850\",",
                           "\"name\": \"VMC-850\", // the test bench");
         },
         "campaign.json:5:", "(JSON has no comments)"},
        {"screw_diameter_in_metres",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"diameter_mm\": 40,",
                           "\"diameter_mm\": 0.04,");
         },
         "campaign.json",
         "screw.diameter_mm: 0.04 mm is no ball screw's (2…500 mm): another unit?"},
        {"density_in_g_per_cm3",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"density_kg_m3\": 7850,",
                           "\"density_kg_m3\": 7.85,");
         },
         "campaign.json", "screw.density_kg_m3: 7.85 kg/m³ is no ball screw's"},
        {"nut_length_in_metres",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"nut_length_mm\": 80,",
                           "\"nut_length_mm\": 0.08,");
         },
         "campaign.json", "nut_length_mm: 0.08 mm is no ball-screw nut's length"},
        {"unknown_quantity",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"quantity\": \"speed\"",
                           "\"quantity\": \"pressure\"");
         },
         "campaign.json", "channels[7].quantity: unknown quantity 'pressure'"},
        {"unknown_role",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"role\": \"structure\"",
                           "\"role\": \"gantry\"");
         },
         "campaign.json", "channels[5].role: unknown role 'gantry'"},
        {"role_of_other_quantity",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"role\": \"drift_x\"", "\"role\": \"nut\"");
         },
         "campaign.json", "channels[8].role: unknown role 'nut' for a displacement channel"},
        {"negative_screw_length",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"length_mm\": 900", "\"length_mm\": -900");
         },
         "campaign.json", "screw.length_mm: must be positive"},
        {"missing_header", [=](const QString& d) { writeFile(file(d, "samples.csv"), "\n\n"); },
         "samples.csv", "missing header line"},
        {"missing_time_column",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "run,time_s,", "run,time,");
         },
         "samples.csv:1", "missing column 'time_s'"},
        {"duplicate_header",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "T_air,T_bed", "T_air,T_air");
         },
         "samples.csv:1:8", "duplicate column 'T_air' in header (also column 7)"},
        {"undeclared_channel",
         [=](const QString& d) { replaceInFile(file(d, "samples.csv"), "T_bed", "T_table"); },
         "samples.csv:1:8", "column 'T_table' is not a channel declared in campaign.json"},
        {"unknown_run",
         [=](const QString& d) { replaceInFile(file(d, "samples.csv"), "\nS1,20,", "\nS9,20,"); },
         "samples.csv:4:1", "unknown run id 'S9'"},
        {"non_numeric_cell",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,20,", "\nS1,20,warm");
         },
         "samples.csv:4:3", "non-numeric cell 'warm"},
        {"nan_cell",
         [=](const QString& d) { replaceInFile(file(d, "samples.csv"), "\nS1,20,", "\nS1,nan,"); },
         "samples.csv:4:2", "NaN or infinite value 'nan' in column 'time_s'"},
        {"inf_cell",
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), "\nS1,0,0,0,+,0.13\n",
                           "\nS1,0,0,0,+,-inf\n");
         },
         "positioning.csv:2:6", "NaN or infinite value"},
        {"time_backwards",
         [=](const QString& d) { replaceInFile(file(d, "samples.csv"), "\nS1,30,", "\nS1,5,"); },
         "samples.csv:5:2", "time goes backwards in run 'S1' (5 s after 20 s)"},
        // One instant has one reading: a repeated time may only fill cells.
        {"two_readings_at_one_instant",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,30,20.12,", "\nS1,20,20.12,");
         },
         "samples.csv:5:3",
         "column 'T_nut' reads 20.12 at 20 s of run 'S1', but 20.08 on line 4 at the same time"},
        // °F and K are converted (BundleReader test); a raw thermocouple voltage is not.
        {"unit_of_no_temperature_in_header",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "run,time_s,T_nut,", "run,time_s,T_nut [mV],");
         },
         "samples.csv:1:3",
         "column 'T_nut [mV]': 'mV' is not a unit DriftLab reads for a temperature channel "
         "(°C, °F or K)"},
        {"channel_twice_in_header",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "T_air,T_bed", "T_air,T_air (degC)");
         },
         "samples.csv:1:8", "column 'T_air (degC)' is channel 'T_air' again"},
        {"value_under_a_trailing_separator",
         [=](const QString& d) {
             QList<QByteArray> lines = readFile(file(d, "samples.csv")).split('\n');
             for (qsizetype i = 0; i < lines.size(); ++i)
                 if (!lines[i].isEmpty()) lines[i] += i == 2 ? ",7" : ",";
             writeFile(file(d, "samples.csv"), lines.join('\n'));
         },
         "samples.csv:3:19", "a value under the unnamed last column: '7'"},
        {"truncated_csv",
         [=](const QString& d) {
             QByteArray csv = readFile(file(d, "samples.csv"));
             writeFile(file(d, "samples.csv"), csv.left(csv.size() - 40));
         },
         "samples.csv:543:", "(truncated line?)"},
        {"deviation_in_mm_by_its_header",
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), "deviation_um", "deviation_mm");
         },
         "positioning.csv:1",
         "missing column 'deviation_um' in header: it has 'deviation_mm', in mm (DriftLab reads "
         "deviation in um: convert the column and name it 'deviation_um')"},
        {"time_without_its_unit",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "run,time_s,", "run,time,");
         },
         "samples.csv:1", "missing column 'time_s' in header: it has 'time', without its unit"},
        {"deviation_renamed",  // further columns are ignored, a required one must be there
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), "deviation_um", "error_um");
         },
         "positioning.csv:1", "missing column 'deviation_um' in header"},
        {"deviation_in_mm_by_a_bracketed_unit",
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), "deviation_um", "Deviation [mm]");
         },
         "positioning.csv:1",
         "missing column 'deviation_um' in header: it has 'Deviation [mm]', in mm (DriftLab reads "
         "deviation in um: convert the column and name it 'deviation_um')"},
        {"two_columns_naming_the_time",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "run,time_s,T_nut,", "run,time_s,Time [s],");
         },
         "samples.csv:1:3", "columns 'time_s' and 'Time [s]' both name 'time_s'"},
        {"number_in_quotes",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"lead_mm\": 10", "\"lead_mm\": \"10\"");
         },
         "campaign.json",
         "screw.lead_mm: expected a number, found the text \"10\" (write a number without "
         "quotes)"},
        {"no_format_key",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"format\": \"driftlab.campaign/1\",", "");
         },
         "campaign.json", "format: missing (a campaign.json names its format: \"format\": "},
        {"bad_direction",
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), ",70,+,", ",70,both,");
         },
         "positioning.csv:3:5", "direction must be + or -, found 'both'"},
        {"kelvin_temperatures",
         [=](const QString& d) {
             rewriteColumn(file(d, "samples.csv"), 2,
                           [](double c) { return QByteArray::number(c + 273.15); });
         },
         "samples.csv:2:3", "looks like kelvin"},
        {"room_in_fahrenheit",
         [=](const QString& d) {
             rewriteColumn(file(d, "samples.csv"), 5,  // T_ambient, role ambient
                           [](double c) { return QByteArray::number(c * 1.8 + 32, 'f', 2); });
         },
         "samples.csv:2:6",
         "column 'T_ambient': 68.02 °C is no room's or air's temperature in a machine-tool lab "
         "(at most 45 °C): °F?"},
        // Issue 9: the kelvin check works per value, not on the median.
        {"one_kelvin_reading_among_celsius",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,980,22.74,", "\nS1,980,295.89,");
         },
         "samples.csv:100:3", "295.89 °C looks like kelvin"},
        {"temperature_of_2000_celsius",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,10,20.06,", "\nS1,10,2000,");
         },
         "samples.csv:3:3", "column 'T_nut': 2000 °C is impossible for a temperature"},
        {"temperature_of_1e308",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,10,20.06,20.02,", "\nS1,10,20.06,1e308,");
         },
         "samples.csv:3:4", "column 'T_bearing_fixed': 1e+308 °C is impossible"},
        {"number_beyond_double_range",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,10,20.06,", "\nS1,10,1e400,");
         },
         "samples.csv:3:3", "out of the range of a number"},
        {"targets_in_micrometres",
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), ",70,+,", ",70000,+,");
         },
         "positioning.csv:3:4", "lies beyond the screw [-80, 900] mm (unit mix-up?"},
        {"position_column_in_micrometres",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), ",423.333,8000,", ",423333,8000,");
         },
         "samples.csv:3:16", "position_mm = 423333 mm lies beyond the screw"},
        {"deviation_in_nanometres",
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), "\nS1,2,0,70,+,0.93\n",
                           "\nS1,2,0,70,+,930000\n");
         },
         "positioning.csv:3:6", "nm instead of µm?"},
        {"time_in_milliseconds",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,10,", "\nS1,36000000,");
         },
         "samples.csv:3:2", "ms instead of s?"},
        {"time_as_an_impossible_date",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,10,", "\nS1,2026-13-45 25:00:00,");
         },
         "samples.csv:3:2",
         "cell '2026-13-45 25:00:00' in column 'time_s' is neither a number nor a date and time"},
        {"time_on_a_unix_clock",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,10,", "\nS1,1795000010,");
         },
         "samples.csv:3:2", "Unix time? time_s counts from the run's start"},
        {"positioning_on_a_unix_clock_beside_samples_from_zero",
         [=](const QString& d) {
             rewriteColumn(file(d, "positioning.csv"), 1,
                           [](double t) { return QByteArray::number(t + 1795000000, 'f', 3); });
         },
         "positioning.csv:155:2",
         "run 'S1': 1795003582 s is beyond 10000000 s since the run's start (Unix time?"},
        {"feed_in_micrometres_per_minute",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), ",423.333,8000,", ",423.333,8000000,");
         },
         "samples.csv:3:17", "column 'feed_mm_min': 8000000 mm/min is beyond ±1000000 mm/min"},
        // Issue 9: RFC 4180 is read, so what breaks it must be named.
        {"stray_quote_inside_a_cell",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,10,20.06,", "\nS1,10,20\"06,");
         },
         "samples.csv:3:3", "malformed quoting"},
        {"unterminated_quote",
         [=](const QString& d) {
             QByteArray csv = readFile(file(d, "samples.csv"));
             writeFile(file(d, "samples.csv"), csv + "S1,3700,\"20.5,20,20,20,20,20\n");
         },
         "samples.csv:544:3", "unterminated quoted field"},
        // Found by fuzzing: a record's fields beyond the header's are not kept.
        {"a_million_commas_in_one_row",
         [=](const QString& d) {
             QByteArray csv = readFile(file(d, "samples.csv"));
             writeFile(file(d, "samples.csv"), csv + "S1,3700" + QByteArray(1'000'000, ',') + "\n");
         },
         "samples.csv:544:19", "expected 18 fields as in the header, found 1000002"},
        {"decimal_comma_in_a_comma_separated_file",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,10,20.06,", "\nS1,10,\"20,06\",");
         },
         "samples.csv:3:3", "non-numeric cell '20,06' in column 'T_nut' (a decimal comma?"},
        {"thousands_separator_in_a_semicolon_file",
         [=](const QString& d) {
             QByteArray csv = readFile(file(d, "samples.csv"));
             csv.replace(',', ';');
             csv.replace("\nS1;10;20.06;", "\nS1;10;1.020,06;");
             writeFile(file(d, "samples.csv"), csv);
         },
         "samples.csv:3:3", "mixes '.' and ','"},
        // A misspelt key whose absence changes a result: the default would be used.
        {"misspelt_expansion_coefficient",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"alpha_per_K\"", "\"alpha_perK\"");
         },
         "campaign.json",
         "screw.alpha_perK: unknown key (did you mean 'alpha_per_K'? without it, alpha_per_K "
         "would be 1.15e-05 per K)"},
        {"misspelt_screw_length",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"length_mm\"", "\"lenght_mm\"");
         },
         "campaign.json", "screw.lenght_mm: unknown key (did you mean 'length_mm'?)"},
        {"dead_path_without_its_unit",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"dead_path_mm\"", "\"dead_path\"");
         },
         "campaign.json",
         "interferometer.dead_path: unknown key (did you mean 'dead_path_mm'? without it, "
         "dead_path_mm would be 0 mm)"},
        {"misspelt_travel",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"travel_mm\"", "\"travel_nm\"");
         },
         "campaign.json",
         "travel_nm: unknown key (did you mean 'travel_mm'? without it, travel_mm would be "
         "absent)"},
        // A cell or value is shown escaped and shortened: the message stays one whole line.
        {"nul_byte_in_a_cell",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,20,", QByteArray("\nS1,20,x\0y", 10));
         },
         "samples.csv:4:3", "non-numeric cell 'x\\0y20.08' in column 'T_nut'"},
        {"three_megabyte_run_id",
         [=](const QString& d) {
             replaceInFile(file(d, "samples.csv"), "\nS1,20,",
                           '\n' + QByteArray(3'000'000, 'A') + ",20,");
         },
         "samples.csv:4:1",
         "unknown run id 'AAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAAA…' (3000000 "
         "bytes) (not in campaign.json)"},
        {"terminal_escape_in_a_json_value",
         [=](const QString& d) {
             replaceInFile(file(d, "campaign.json"), "\"quantity\": \"speed\"",
                           "\"quantity\": \"\\u001b[2Jspeed\"");
         },
         "campaign.json", "channels[7].quantity: unknown quantity '\\x1b[2Jspeed'"},
        // An integer beyond the range of its column is no non-integer.
        {"cycle_beyond_the_integer_range",
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), "\nS1,0,0,0,+,0.13\n",
                           "\nS1,0,99999999999,0,+,0.13\n");
         },
         "positioning.csv:2:3",
         "value '99999999999' in column 'cycle' is out of range: an integer from 0 to 2147483647 "
         "is expected"},
        {"negative_cycle",
         [=](const QString& d) {
             replaceInFile(file(d, "positioning.csv"), "\nS1,0,0,0,+,0.13\n",
                           "\nS1,0,-1,0,+,0.13\n");
         },
         "positioning.csv:2:3",
         "value '-1' in column 'cycle' is out of range: an integer from 0 to 2147483647 is "
         "expected"},
        {"motion_ends_before_start",
         [=](const QString& d) {
             replaceInFile(file(d, "motion.csv"), "S1,0.000,2.100,", "S1,0.000,-2.100,");
         },
         "motion.csv:2:3", "segment ends (-2.1 s) before it starts (0 s)"},
    };
    return cases;
}

}  // namespace driftlab::test
