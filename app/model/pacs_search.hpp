#pragma once

// The operator's words for a PACS search (docs/dicom-network.md "The kiosk's search"): the keys
// of a study search as the workflow's SearchPacs carries them, the fields a site may put on the
// kiosk's form ([dicom] search_fields) and the date presets its chips offer
// ([dicom] search_date_presets). Plain values: the config, the workflow, the script and the
// panel name them without the network.
#include <chrono>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::model {

// The keys of a study search; "" matches anything. `studyDate` is YYYYMMDD, YYYYMMDD-YYYYMMDD
// or a preset's name ("last_7_days"): a preset is turned into dates when the search runs, so a
// search repeated from the audit log asks for the days around its own moment.
struct PacsKeys {
    std::string patientName; // with * and ? as wildcards ("DOE*")
    std::string patientId;
    std::string studyDate;
    std::string modality;
    std::string accession;
    bool operator==(const PacsKeys&) const = default;
};

enum class SearchField { PatientName, PatientId, StudyDate, Modality, Accession };
inline constexpr std::size_t kSearchFieldCount = 5;
// "patient_name", "patient_id", "study_date", "modality", "accession": the config's and the
// script's words.
std::string_view searchFieldName(SearchField field);
std::optional<SearchField> searchFieldFromName(std::string_view name);
const std::vector<std::string_view>& searchFieldNames();
// The form's words: "Patient name", "Patient ID", "Study date", "Modality", "Accession".
std::string_view searchFieldLabel(SearchField field);
std::string& keyOf(PacsKeys& keys, SearchField field);
const std::string& keyOf(const PacsKeys& keys, SearchField field);

enum class DatePreset { Any, Today, Yesterday, Last7Days, Last30Days };
// "any", "today", "yesterday", "last_7_days", "last_30_days".
std::string_view datePresetName(DatePreset preset);
std::optional<DatePreset> datePresetFromName(std::string_view name);
const std::vector<std::string_view>& datePresetNames();
// The chips' words: "Any date", "Today", "Yesterday", "Last 7 days", "Last 30 days".
std::string_view datePresetLabel(DatePreset preset);

// `studyDate` as the PACS is asked: a preset's days counted back from `today` (the console's
// local date; "last 7 days" is today and the six before it), anything else as given.
std::string studyDateFor(std::string_view studyDate, std::chrono::year_month_day today);

// "" when `uid` is a DICOM UID (digits and dots, 1 to 64), else why not.
std::string uidProblem(std::string_view uid);
// "" when every key is printable ASCII within 64 characters and the date is a preset, a date
// or a range of digits; else the first problem, naming its key. The network checks the dates'
// calendar before it asks.
std::string pacsKeysProblem(const PacsKeys& keys);

} // namespace steerseg::model
