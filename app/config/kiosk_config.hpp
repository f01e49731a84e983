#pragma once

// The kiosk's settings as one plain value. The defaults here are the shipped file
// config/steerseg.toml, which documents every key; a unit test keeps the two equal.
#include "model/speed_kind.hpp" // the enum only: config links no speed code
#include "model/structure.hpp"

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace steerseg::config {

enum class DisplayPlatform { Auto, Kms, Window, Offscreen };
std::string_view platformName(DisplayPlatform platform); // "auto", "kms", "window", "offscreen"
std::optional<DisplayPlatform> parsePlatform(std::string_view word);

struct DisplayConfig {
    DisplayPlatform platform = DisplayPlatform::Auto;
    int width = 1280; // window and offscreen size
    int height = 800;
    bool fullscreen = false; // window backend
    std::string drmDevice;   // kms: "" = the first card with a connected connector
    std::string connector;   // kms: "" = the first connected one
    std::string mode;        // kms: "1920x1080" or "1920x1080@60", "" = the preferred mode
    int rotation = 0;        // degrees clockwise: 0, 90, 180, 270
    double dpi = 0.0;        // 0 = from the display's physical size
    // kms: libinput's calibration matrix for the touchscreen, six numbers "a b c d e f"
    // (udev's LIBINPUT_CALIBRATION_MATRIX form); "" = what udev sets, else none.
    std::string touchCalibration;
    bool operator==(const DisplayConfig&) const = default;
};

struct FrameConfig {
    double budgetMs = 33.0;        // one frame, input to present
    double solverShare = 0.5;      // the part of the budget the solver may take
    int minIterations = 1;         // per frame while evolving, however slow the GPU
    int maxIterations = 64;        // per frame, however fast
    double interactiveScale = 0.5; // 3D view resolution while the camera or surface moves
    bool operator==(const FrameConfig&) const = default;
};

struct UiConfig {
    double touchTargetMm = 9.0;
    double fontScale = 1.0;
    int longPressMs = 500;
    bool operator==(const UiConfig&) const = default;
};

struct ProbeConfig {
    double radiusMm = 5.0;
    double epsFactor = 2.0; // eps = stddev * factor ...
    double epsFloor = 10.0; // ... but at least this (real units)
    bool operator==(const ProbeConfig&) const = default;
};

struct BrushConfig {
    double radius = 3.0;          // voxels
    double correctionReach = 3.0; // brush radii around a correction its run may move (0: all)
    double eraseRunGrowth = 0.25; // an erase's global run's growth before it is taken back
    double eraseWithdrawMm = 4.0; // how far an erase's run takes the surface back beyond reach
    bool operator==(const BrushConfig&) const = default;
};

// The speed function after a load (docs/speed.md) and the edge speed's preprocessing. The
// smoothing (speed::SmoothingParams) and kappa (speed::edgeFactor) are in the scan's real
// units there; here they are fractions of the scan's value range (max - min), so one file
// serves CT in HU and MR in arbitrary units.
struct SpeedConfig {
    // Classify: the threshold speed until the operator's first outside example (an erase while
    // steering, an outside mark), then a surface that learns from every correction
    // (docs/steering.md: the clicks protocol's negative cases only improved this way).
    model::SpeedKind kind = model::SpeedKind::Classify;
    // The edge speed's preprocessing, from the noise the last probe measured (as segment
    // --probe: session/speed_probe.hpp), so one file serves CT and MR.
    int smoothIterations = 5;       // anisotropic diffusion steps before the edge factor, 0 = none
    double conductanceFactor = 3.0; // diffusion conductance K = factor * the probe's noise
    double kappaFactor = 1.0;       // kappa = factor * the probe's noise (per voxel)
    // Classify bounded by the threshold's window (workflow::Settings::classifyWithinWindow).
    bool classifyWithinWindow = true;
    // Classify: how far, in its radii, an example decides where the classifier is unsure
    // (workflow::Settings::classifyPlaceReach).
    double classifyPlaceReach = 3.0;
    bool operator==(const SpeedConfig&) const = default;
};

struct ExportConfig {
    std::filesystem::path folder = "steerseg-export";
    std::vector<std::string> formats{"nii.gz"}; // one mask file per format
    bool operator==(const ExportConfig&) const = default;
};

struct AuditConfig {
    std::filesystem::path path = "steerseg-export/audit.jsonl";
    bool operator==(const AuditConfig&) const = default;
};

// Autosave of the operator's session for resume after a crash (docs/kiosk.md).
struct AutosaveConfig {
    std::filesystem::path folder = "steerseg-export/autosave";
    double intervalSeconds = 10.0; // while evolving; every transition saves too
    int keep = 5;                  // the newest this many are kept
    bool operator==(const AutosaveConfig&) const = default;
};

// A one-touch tissue preset: the speed function's parameters and the view that goes with them.
struct Preset {
    std::string name;
    double T = 0.0;   // real units
    double eps = 0.0; // real units
    double alpha = 1.0;
    double windowLevel = 0.0;
    double windowWidth = 1.0;
    std::string transfer; // transfer-function preset, render's words: "soft", "bone", "mr"
    bool operator==(const Preset&) const = default;
};

// What a key, knob or button does: a bindable action of the workflow (model::bindableNames)
// and how many of its steps one press or detent makes (-1 turns "nudge_selected" into a minus).
// A button or pedal may also name what its release does (`release`, "" = nothing), so a
// pedal can run while held: { action = "run", release = "pause" }.
struct Binding {
    std::string action;
    double steps = 1.0;
    std::string release;
    bool operator==(const Binding&) const = default;
};
using BindingTable = std::map<std::string, Binding, std::less<>>;

struct BindingsConfig {
    BindingTable keys;    // key names of platform/input_event.hpp, optionally "ctrl+" / "shift+"
    BindingTable knobs;   // control names of the input devices (devices issue)
    BindingTable buttons; // buttons and pedals, likewise
    bool operator==(const BindingsConfig&) const = default;
};

// One configured input device ([[input.devices]]); the kiosk turns it into a
// platform::input::DeviceSpec (config may not include platform/). Which fields apply depends on
// the kind: HID ids and usages for shuttle and radial (and the PowerMate without a path), chip
// and line for the GPIO kinds.
enum class InputDeviceKind { Shuttle, Radial, PowerMate, GpioInput, GpioLed };
// "shuttle", "radial", "powermate", "gpio_input", "gpio_led"
std::string_view inputDeviceKindName(InputDeviceKind kind);
std::optional<InputDeviceKind> parseInputDeviceKind(std::string_view word);

struct InputDeviceConfig {
    std::string name; // control-name alphabet; prefix of its controls ("shuttle" -> shuttle_jog)
    InputDeviceKind kind = InputDeviceKind::Shuttle;
    int vendorId = 0; // 0..0xffff; 0 = any
    int productId = 0;
    int usagePage = 0;
    int usage = 0;
    std::string path; // evdev node; "" = found by vendor/product id
    std::string chip; // GPIO chip name or label
    std::string line; // GPIO line name, or its offset as digits
    bool activeLow = false;
    double debounceMs = 20.0;
    bool operator==(const InputDeviceConfig&) const = default;
};

struct InputConfig {
    std::vector<InputDeviceConfig> devices; // a file's [[input.devices]] replaces the list
    bool operator==(const InputConfig&) const = default;
};

// [dicom] (docs/dicom-network.md): the DICOM node, off unless `enabled`. A peer may send to the
// console (`receive`), be a target of exports (`send`), be queried and retrieved from (`query`),
// or any of them.
struct DicomPeerConfig {
    std::string name; // how --to and the panel name it
    std::string aet;
    std::string host;
    int port = 104;
    std::string address; // receive: the caller's IP address to insist on, "" = any
    bool receive = false;
    bool send = false;
    bool tls = false;   // sent to, and calling in, over TLS only
    bool query = false; // `steerseg query` / `retrieve` may ask it (C-FIND, C-GET or C-MOVE)
    // How a retrieve asks for images: C-GET on the query's own association (no inbound port),
    // or C-MOVE to the node's own AE title (the PACS calls the node's port).
    enum class Retrieve { Get, Move };
    Retrieve retrieve = Retrieve::Get;
    bool operator==(const DicomPeerConfig&) const = default;
};

struct DicomConfig {
    bool enabled = false;
    std::string aet = "STEERSEG";
    int port = 11112;
    std::filesystem::path store = "steerseg-incoming";
    std::filesystem::path outbox = "steerseg-export/outbox";
    int associationQuotaMb = 1024;      // bytes one association may bring (and hold in memory)
    int minFreeMb = 256;                // refuse objects that would leave less free in the store
    int keepDays = 7;                   // received series older than this are removed
    int maxAssociations = 4;            // served at once; one more is rejected as busy
    int negotiationSeconds = 5;         // a connection's time to send its association request
    double retryFirstSeconds = 5.0;     // the outbox's delay after a failed send ...
    double retryLongestSeconds = 300.0; // ... doubled after each further one up to this
    // TLS (docs/dicom-network.md): the node's certificate and unencrypted private key (PEM), the
    // CA certificates it trusts (a PEM file or a folder of them); "" = none.
    std::filesystem::path tlsCertificate;
    std::filesystem::path tlsPrivateKey;
    std::filesystem::path tlsCaCertificates;
    bool tlsReceive = false; // the port speaks TLS only; the receive peers need tls = true
    // The kiosk's PACS search (docs/dicom-network.md "The kiosk's search"): the form's fields
    // (model::searchFieldNames) and date chips (model::datePresetNames), in the form's order,
    // and how long a search or a retrieve waits for a peer's each answer.
    std::vector<std::string> searchFields{"patient_name", "patient_id", "study_date", "modality"};
    std::vector<std::string> searchDatePresets{"today", "yesterday", "last_7_days", "last_30_days",
                                               "any"};
    int queryTimeoutSeconds = 10;
    std::vector<DicomPeerConfig> peers; // a file's [[dicom.peers]] replaces the list
    bool operator==(const DicomConfig&) const = default;
};

// How the session's structures relate (docs/structures.md).
struct SegmentationConfig {
    bool structuresOverlap = false; // false: the other structures are barriers to the active one
    bool operator==(const SegmentationConfig&) const = default;
};

struct KioskConfig {
    DisplayConfig display;
    FrameConfig frame;
    UiConfig ui;
    ProbeConfig probe;
    BrushConfig brush;
    SpeedConfig speed;
    ExportConfig exports;
    AuditConfig audit;
    AutosaveConfig autosave;
    std::vector<Preset> presets; // in the order the panel shows them
    // The site's structures ([[structures]]): names the panel offers, with their codes.
    std::vector<model::StructureInfo> structures;
    SegmentationConfig segmentation;
    BindingsConfig bindings;
    InputConfig input;
    DicomConfig dicom;
    bool operator==(const KioskConfig&) const = default;
};

// The built-in defaults, equal to the shipped config/steerseg.toml.
KioskConfig defaultConfig();

} // namespace steerseg::config
