#pragma once

// Internal to config: one reader per part of the file, each writing the fields its table gives
// into a copy of the configuration and reporting every problem through the table reader.
#include "config/config_loader.hpp"
#include "config/kiosk_config.hpp"
#include "config/toml_table_reader.hpp"

namespace steerseg::config::detail {

void readDisplay(TableReader& table, DisplayConfig& display);
void readFrame(TableReader& table, FrameConfig& frame);
void readUi(TableReader& table, UiConfig& ui);
void readProbe(TableReader& table, ProbeConfig& probe);
void readBrush(TableReader& table, BrushConfig& brush);
void readSpeed(TableReader& table, SpeedConfig& speed);
void readExport(TableReader& table, ExportConfig& exports);
void readAudit(TableReader& table, AuditConfig& audit);
void readAutosave(TableReader& table, AutosaveConfig& autosave);
void readDicom(TableReader& table, DicomConfig& dicom); // with its [[dicom.peers]]
// The TLS keys of [dicom] and its peers: each named file there and a PEM of its kind, and TLS
// asked for only with the node's certificate, key and CAs (config_dicom_tls).
void checkDicomTls(const DicomConfig& dicom, const toml::table& root, ProblemSink& sink);

// [[preset]]: an entry whose name is already a preset changes the fields it gives; a new name
// appends a preset and must give every field.
void readPresets(const toml::array& entries, std::vector<Preset>& presets, ProblemSink& sink);

// [[structures]]: a file that has the array replaces the site's list whole; each entry a name,
// category and type codes ([value, scheme, meaning]) and an optional colour.
void readStructures(const toml::array& entries, std::vector<model::StructureInfo>& kinds,
                    ProblemSink& sink);
void readSegmentation(TableReader& table, SegmentationConfig& segmentation);

// [[input.devices]]: a file that has the array replaces the whole list (an empty array
// configures no device); each entry gives a name and a kind, and the fields its kind uses.
void readInputDevices(const toml::array& entries, std::vector<InputDeviceConfig>& devices,
                      ProblemSink& sink);

// [bindings.keys], [bindings.knobs], [bindings.buttons], name -> action, key by key.
void readBindings(TableReader& table, BindingsConfig& bindings, const BindingCheck& check);

// Relations between keys, checked on the configuration a file would produce (`root` locates
// the problem in that file).
void checkRelations(const KioskConfig& config, const toml::table& root, ProblemSink& sink);

} // namespace steerseg::config::detail
