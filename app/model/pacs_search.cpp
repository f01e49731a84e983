#include "model/pacs_search.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <optional>

namespace steerseg::model {
namespace {

constexpr std::array<std::string_view, kSearchFieldCount> kFieldNames{
    "patient_name", "patient_id", "study_date", "modality", "accession"};
constexpr std::array<std::string_view, kSearchFieldCount> kFieldLabels{
    "Patient name", "Patient ID", "Study date", "Modality", "Accession"};
constexpr std::array<std::string_view, 5> kPresetNames{"any", "today", "yesterday", "last_7_days",
                                                       "last_30_days"};
constexpr std::array<std::string_view, 5> kPresetLabels{"Any date", "Today", "Yesterday",
                                                        "Last 7 days", "Last 30 days"};
constexpr std::size_t kMaxKey = 64; // DICOM's longest string VR (LO) in a query

std::string yyyymmdd(std::chrono::year_month_day d) {
    char text[16];
    std::snprintf(text, sizeof text, "%04d%02u%02u", static_cast<int>(d.year()),
                  static_cast<unsigned>(d.month()), static_cast<unsigned>(d.day()));
    return text;
}

std::chrono::year_month_day daysBefore(std::chrono::year_month_day d, int days) {
    return std::chrono::year_month_day(std::chrono::sys_days(d) - std::chrono::days(days));
}

// One enum's value by its config name, and the names in order: the fields' and the presets'.
template <typename Enum, std::size_t N>
std::optional<Enum> fromName(const std::array<std::string_view, N>& names, std::string_view name) {
    const auto* it = std::find(names.begin(), names.end(), name);
    if (it == names.end()) {
        return std::nullopt;
    }
    return static_cast<Enum>(it - names.begin());
}

} // namespace

std::string_view searchFieldName(SearchField field) {
    return kFieldNames.at(static_cast<std::size_t>(field));
}

std::optional<SearchField> searchFieldFromName(std::string_view name) {
    return fromName<SearchField>(kFieldNames, name);
}

const std::vector<std::string_view>& searchFieldNames() {
    static const std::vector<std::string_view> names(kFieldNames.begin(), kFieldNames.end());
    return names;
}

std::string_view searchFieldLabel(SearchField field) {
    return kFieldLabels.at(static_cast<std::size_t>(field));
}

std::string& keyOf(PacsKeys& keys, SearchField field) {
    switch (field) {
    case SearchField::PatientName:
        return keys.patientName;
    case SearchField::PatientId:
        return keys.patientId;
    case SearchField::StudyDate:
        return keys.studyDate;
    case SearchField::Modality:
        return keys.modality;
    case SearchField::Accession:
        break;
    }
    return keys.accession;
}

const std::string& keyOf(const PacsKeys& keys, SearchField field) {
    return keyOf(const_cast<PacsKeys&>(keys), field); // NOLINT: the same member, read only
}

std::string_view datePresetName(DatePreset preset) {
    return kPresetNames.at(static_cast<std::size_t>(preset));
}

std::optional<DatePreset> datePresetFromName(std::string_view name) {
    return fromName<DatePreset>(kPresetNames, name);
}

const std::vector<std::string_view>& datePresetNames() {
    static const std::vector<std::string_view> names(kPresetNames.begin(), kPresetNames.end());
    return names;
}

std::string_view datePresetLabel(DatePreset preset) {
    return kPresetLabels.at(static_cast<std::size_t>(preset));
}

std::string studyDateFor(std::string_view studyDate, std::chrono::year_month_day today) {
    const std::optional<DatePreset> preset = datePresetFromName(studyDate);
    if (!preset) {
        return std::string(studyDate);
    }
    switch (*preset) {
    case DatePreset::Any:
        return "";
    case DatePreset::Today:
        return yyyymmdd(today);
    case DatePreset::Yesterday:
        return yyyymmdd(daysBefore(today, 1));
    case DatePreset::Last7Days:
        return yyyymmdd(daysBefore(today, 6)) + "-" + yyyymmdd(today);
    case DatePreset::Last30Days:
        return yyyymmdd(daysBefore(today, 29)) + "-" + yyyymmdd(today);
    }
    return "";
}

std::string uidProblem(std::string_view uid) {
    if (uid.empty() || uid.size() > kMaxKey || !std::all_of(uid.begin(), uid.end(), [](char c) {
            return c == '.' || (c >= '0' && c <= '9');
        })) {
        return "'" + std::string(uid.substr(0, kMaxKey)) +
               "' is not a DICOM UID (1 to 64 digits and dots)";
    }
    return "";
}

std::string pacsKeysProblem(const PacsKeys& keys) {
    for (std::size_t i = 0; i < kSearchFieldCount; ++i) {
        const auto field = static_cast<SearchField>(i);
        const std::string& key = keyOf(keys, field);
        if (key.size() > kMaxKey ||
            !std::all_of(key.begin(), key.end(), [](char c) { return c >= ' ' && c <= '~'; })) {
            return std::string(searchFieldName(field)) +
                   ": must be printable ASCII of at most 64 characters";
        }
    }
    const std::string& date = keys.studyDate;
    if (!date.empty() && !datePresetFromName(date) &&
        !std::all_of(date.begin(), date.end(),
                     [](char c) { return c == '-' || (c >= '0' && c <= '9'); })) {
        return "study_date: must be YYYYMMDD, YYYYMMDD-YYYYMMDD or one of any, today, yesterday, "
               "last_7_days, last_30_days";
    }
    return "";
}

} // namespace steerseg::model
