// The load screen's PACS search without a GPU: the form typed on the on-screen keyboard, the
// date chips, the peer choice, and the panel model built from the node's Status::pacs (fields
// as the site's config lists them, Search with the form's keys to the chosen peer, the results
// as Retrieve and Series, a study's series each with its Retrieve, the progress bar and
// Cancel), plus the dates a chip asks for.
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

// Two query peers: one button each, the first chosen by default, Search asking the chosen one;
// the results retrieve and list series from the peer they were found on, whichever is chosen
// now. One peer: no choice shown.
TEST(UiPacsSearch, APeerChoiceWhereTheSiteHasSeveral) {
    workflow::PacsView v = view();
    ui::PanelModel m = ui::buildPanelModel(loadScreen(v), {});
    ASSERT_TRUE(m.pacs);
    EXPECT_TRUE(m.pacs->peers.empty()) << "one peer: nothing to choose";
    EXPECT_EQ(std::get<model::SearchPacs>(m.pacs->search.action).peer, "pacs");

    v.peers = {"pacs", "archive"};
    v.studies = {{"1.2.3", "a"}};
    v.studiesPeer = "archive";
    m = ui::buildPanelModel(loadScreen(v), {});
    ASSERT_EQ(m.pacs->peers.size(), 2U);
    EXPECT_EQ(m.pacs->peers[0].label, "pacs##pacs_peer_pacs");
    EXPECT_TRUE(m.pacs->peers[0].chosen) << "the first by default";
    EXPECT_FALSE(m.pacs->peers[1].chosen);
    EXPECT_EQ(std::get<model::SearchPacs>(m.pacs->search.action).peer, "pacs");

    ui::PanelEditors editors;
    editors.pacsPeer = "archive";
    m = ui::buildPanelModel(loadScreen(v), {}, editors);
    EXPECT_FALSE(m.pacs->peers[0].chosen);
    EXPECT_TRUE(m.pacs->peers[1].chosen);
    EXPECT_EQ(std::get<model::SearchPacs>(m.pacs->search.action).peer, "archive");
    // The study found on archive goes on asking archive, whatever the form chooses now.
    editors.pacsPeer = "pacs";
    m = ui::buildPanelModel(loadScreen(v), {}, editors);
    EXPECT_EQ(std::get<model::SearchPacs>(m.pacs->search.action).peer, "pacs");
    EXPECT_EQ(std::get<model::RetrievePacs>(m.pacs->results[0].action).peer, "archive");
    EXPECT_EQ(std::get<model::ListPacsSeries>(m.pacs->seriesOf[0].action).peer, "archive");
    // A name the config no longer has: the first again.
    editors.pacsPeer = "gone";
    m = ui::buildPanelModel(loadScreen(v), {}, editors);
    EXPECT_TRUE(m.pacs->peers[0].chosen);
    EXPECT_EQ(std::get<model::SearchPacs>(m.pacs->search.action).peer, "pacs");

    // The form keeps the choice while the status offers it, and drops it when not.
    ui::PacsForm form;
    EXPECT_EQ(form.peer(), "");
    form.choosePeer("archive");
    form.follow(v, true);
    EXPECT_EQ(form.peer(), "archive");
    v.peers = {"pacs"};
    form.follow(v, true);
    EXPECT_EQ(form.peer(), "") << "archive left the config";
}

// Series beside each study; the listed study's series under it, each row its modality, number,
// description and images with a Retrieve of that series alone; the whole study's Retrieve
// stays. A listing running shows its line; one of a study this search did not find is not shown.
TEST(UiPacsSearch, AStudysSeriesEachWithItsOwnRetrieve) {
    workflow::PacsView v = view();
    v.studies = {{"1.2.3", "a"}, {"1.2.4", "b"}};
    v.studiesPeer = "pacs";
    ui::PanelModel m = ui::buildPanelModel(loadScreen(v), {});
    ASSERT_TRUE(m.pacs);
    ASSERT_EQ(m.pacs->seriesOf.size(), 2U);
    EXPECT_EQ(m.pacs->seriesOf[1].label, "Series##pacs_series_of1");
    const auto& list = std::get<model::ListPacsSeries>(m.pacs->seriesOf[1].action);
    EXPECT_EQ(list.studyUid, "1.2.4");
    EXPECT_EQ(list.peer, "pacs");
    EXPECT_FALSE(m.pacs->seriesOf[1].active);
    EXPECT_FALSE(m.pacs->seriesStudy);
    EXPECT_TRUE(m.pacs->series.empty());

    // Listing: the line, no rows yet, the study's Series highlighted.
    v.listingSeries = true;
    v.seriesStudyUid = "1.2.4";
    v.seriesPeer = "pacs";
    v.seriesLine = "listing the series on pacs...";
    m = ui::buildPanelModel(loadScreen(v), {});
    ASSERT_TRUE(m.pacs->seriesStudy);
    EXPECT_EQ(*m.pacs->seriesStudy, 1U);
    EXPECT_TRUE(m.pacs->seriesOf[1].active);
    EXPECT_FALSE(m.pacs->seriesOf[0].active);
    EXPECT_EQ(m.pacs->seriesLine, "listing the series on pacs...");
    EXPECT_TRUE(m.pacs->series.empty());

    v.listingSeries = false;
    v.seriesListings = 1;
    v.seriesLine = "2 series of the study on pacs";
    v.series = {{"1.2.4.1", "CT", "3", "Chest 1 mm", 60}, {"1.2.4.2", "SEG", "", "", -1}};
    m = ui::buildPanelModel(loadScreen(v), {});
    ASSERT_EQ(m.pacs->series.size(), 2U);
    EXPECT_EQ(m.pacs->series[0].label, "Retrieve CT  #3  Chest 1 mm  (60 images)##pacs_series0");
    EXPECT_EQ(m.pacs->series[1].label, "Retrieve SEG##pacs_series1")
        << "what was not said, left out";
    const auto& one = std::get<model::RetrievePacs>(m.pacs->series[0].action);
    EXPECT_EQ(one.studyUid, "1.2.4");
    EXPECT_EQ(one.seriesUid, "1.2.4.1");
    EXPECT_EQ(one.peer, "pacs");
    EXPECT_EQ(std::get<model::RetrievePacs>(m.pacs->results[1].action).seriesUid, "")
        << "the whole study's Retrieve stays";
    EXPECT_TRUE(m.pacs->series[0].enabled);
    // Every Series and every series' Retrieve reachable by touch.
    std::size_t lists = 0;
    std::size_t seriesRetrieves = 0;
    for (const model::Action& a : ui::reachableActions(m)) {
        lists += std::holds_alternative<model::ListPacsSeries>(a);
        if (const auto* r = std::get_if<model::RetrievePacs>(&a)) {
            seriesRetrieves += r->seriesUid.empty() ? 0 : 1;
        }
    }
    EXPECT_EQ(lists, 2U);
    EXPECT_EQ(seriesRetrieves, 2U);

    // A retrieve under way: one at a time, the series' too.
    v.retrieving = true;
    m = ui::buildPanelModel(loadScreen(v), {});
    EXPECT_FALSE(m.pacs->series[0].enabled);
    // A new search that did not find the study: its series are not shown.
    v.retrieving = false;
    v.studies = {{"1.2.9", "c"}};
    m = ui::buildPanelModel(loadScreen(v), {});
    EXPECT_FALSE(m.pacs->seriesStudy);
    EXPECT_TRUE(m.pacs->series.empty());
    EXPECT_FALSE(m.pacs->seriesOf[0].active);
    EXPECT_EQ(ui::pacsSeriesLabel({"1.2", "", "", "", -1}), "series");
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
