// The load screen's PACS search without a GPU: the form typed on the on-screen keyboard, the
// date chips, and the panel model built from the node's Status::pacs (fields as the site's
// config lists them, Search with the form's keys, the results as Retrieve, the progress bar
// and Cancel), plus the dates a chip asks for.
#include "ui/pacs_form.hpp"
#include "ui/panel_model.hpp"
#include "workflow/transition_table.hpp"

#include <gtest/gtest.h>

namespace steerseg {
namespace {

using model::SearchField;

void type(ui::PacsForm& form, const std::string& text) {
    for (const char c : text) {
        form.press(ui::Key{ui::KeyKind::Character, c});
    }
}

workflow::PacsView view() {
    workflow::PacsView v;
    v.peers = {"pacs"};
    v.fields = {"patient_id", "study_date", "modality"};
    v.datePresets = {"today", "last_7_days"};
    return v;
}

workflow::Status loadScreen(const workflow::PacsView& v) {
    workflow::Status st;
    st.state = model::State::NoScan;
    st.allowed = workflow::allowedActions(st.state, workflow::factsOf(st));
    st.pacs = v;
    return st;
}

TEST(UiPacsSearch, TheKeyboardFillsTheFieldAndCancelLeavesIt) {
    ui::PacsForm form;
    form.openField(SearchField::PatientId);
    ASSERT_TRUE(form.keyboardOpen());
    type(form, "pid-7");
    form.press(ui::Key{ui::KeyKind::Ok});
    EXPECT_FALSE(form.keyboardOpen());
    EXPECT_EQ(form.keys().patientId, "pid-7");
    form.openField(SearchField::PatientId);
    EXPECT_EQ(form.keyboard()->text(), "pid-7") << "the keyboard holds what the field has";
    type(form, "99");
    form.press(ui::Key{ui::KeyKind::Cancel});
    EXPECT_EQ(form.keys().patientId, "pid-7");
    // A name's keyboard has the wildcards; a chip toggles the date.
    const std::string punctuation = ui::keyboardFor(SearchField::PatientName).punctuation;
    EXPECT_NE(punctuation.find('*'), std::string::npos);
    EXPECT_NE(punctuation.find('^'), std::string::npos);
    form.choosePreset("today");
    EXPECT_EQ(form.keys().studyDate, "today");
    form.choosePreset("today");
    EXPECT_EQ(form.keys().studyDate, "");
    // Off the load screen the keyboard closes.
    form.openField(SearchField::Modality);
    form.follow(view(), false);
    EXPECT_FALSE(form.keyboardOpen());
}

TEST(UiPacsSearch, ThePanelOffersTheSitesFieldsChipsSearchAndResults) {
    workflow::PacsView v = view();
    v.studies = {{"1.2.3", "2024-01-05  DOE JANE (ID PID-A)  CT"}, {"1.2.4", "other"}};
    model::PacsKeys keys;
    keys.patientId = "PID-A";
    keys.studyDate = "last_7_days";
    const ui::PanelModel m = ui::buildPanelModel(loadScreen(v), {"builtin:sample"},
                                                 ui::PanelEditors{false, false, keys});
    ASSERT_TRUE(m.pacs);
    ASSERT_EQ(m.pacs->fields.size(), 3U);
    EXPECT_EQ(m.pacs->fields[0].field, SearchField::PatientId);
    EXPECT_EQ(m.pacs->fields[0].label, "Patient ID: PID-A##pacs_patient_id");
    EXPECT_EQ(m.pacs->fields[1].label, "Study date: -##pacs_study_date") << "a chip's date";
    ASSERT_EQ(m.pacs->dates.size(), 2U);
    EXPECT_FALSE(m.pacs->dates[0].chosen);
    EXPECT_TRUE(m.pacs->dates[1].chosen);
    EXPECT_EQ(m.pacs->dates[1].label, "Last 7 days##pacs_date_last_7_days");
    const auto& search = std::get<model::SearchPacs>(m.pacs->search.action);
    EXPECT_EQ(search.keys, keys);
    EXPECT_TRUE(m.pacs->search.enabled);
    ASSERT_EQ(m.pacs->results.size(), 2U);
    EXPECT_EQ(std::get<model::RetrievePacs>(m.pacs->results[1].action).studyUid, "1.2.4");
    EXPECT_FALSE(m.pacs->progress) << "no retrieve yet";
    // Search and each Retrieve are reachable by touch; the fields are the form's, no action.
    std::size_t pacsActions = 0;
    for (const model::Action& a : ui::reachableActions(m)) {
        pacsActions += std::holds_alternative<model::SearchPacs>(a) ||
                       std::holds_alternative<model::RetrievePacs>(a);
    }
    EXPECT_EQ(pacsActions, 3U);
}

TEST(UiPacsSearch, ARetrieveShowsItsProgressAndCancelEvenOffTheLoadScreen) {
    workflow::PacsView v = view();
    v.studies = {{"1.2.3", "a"}};
    v.retrieving = true;
    v.received = 12;
    v.expected = 60;
    v.retrieveLine = "retrieving 12 of 60 images from pacs...";
    ui::PanelModel m = ui::buildPanelModel(loadScreen(v), {});
    ASSERT_TRUE(m.pacs && m.pacs->progress);
    EXPECT_DOUBLE_EQ(*m.pacs->progress, 0.2);
    EXPECT_EQ(m.pacs->progressText, "12 of 60 images");
    ASSERT_TRUE(m.pacs->cancel);
    EXPECT_TRUE(std::holds_alternative<model::CancelRetrieve>(m.pacs->cancel->action));
    EXPECT_FALSE(m.pacs->results[0].enabled) << "one retrieve at a time";
    // Evolving: no form, the bar and Cancel stay.
    workflow::Status st = loadScreen(v);
    st.state = model::State::Evolving;
    st.allowed = workflow::allowedActions(st.state, workflow::factsOf(st));
    m = ui::buildPanelModel(st, {});
    ASSERT_TRUE(m.pacs);
    EXPECT_TRUE(m.pacs->fields.empty());
    EXPECT_TRUE(m.pacs->results.empty());
    EXPECT_TRUE(m.pacs->cancel);
    // Before the PACS says how many: the count alone.
    v.expected = 0;
    m = ui::buildPanelModel(loadScreen(v), {});
    EXPECT_LT(*m.pacs->progress, 0.0);
    EXPECT_EQ(m.pacs->progressText, "12 images");
    // Ended: no Cancel; the peer list empty (no query peer): no section at all.
    v.retrieving = false;
    v.retrieves = 1;
    EXPECT_FALSE(ui::buildPanelModel(loadScreen(v), {}).pacs->cancel);
    v.peers.clear();
    EXPECT_FALSE(ui::buildPanelModel(loadScreen(v), {}).pacs);
}

TEST(UiPacsSearch, DatePresetsCountBackFromToday) {
    using namespace std::chrono;
    const year_month_day today{year(2024), month(3), day(2)};
    EXPECT_EQ(model::studyDateFor("today", today), "20240302");
    EXPECT_EQ(model::studyDateFor("yesterday", today), "20240301");
    EXPECT_EQ(model::studyDateFor("last_7_days", today), "20240225-20240302"); // a leap year
    EXPECT_EQ(model::studyDateFor("last_30_days", today), "20240202-20240302");
    EXPECT_EQ(model::studyDateFor("any", today), "");
    EXPECT_EQ(model::studyDateFor("20230101-20231231", today), "20230101-20231231");
    model::PacsKeys bad;
    bad.studyDate = "last week";
    EXPECT_NE(model::pacsKeysProblem(bad).find("study_date"), std::string::npos);
    EXPECT_NE(model::uidProblem("1.2.a").find("not a DICOM UID"), std::string::npos);
    EXPECT_EQ(model::uidProblem("1.2.840.10008"), "");
}

} // namespace
} // namespace steerseg
