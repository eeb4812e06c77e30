#pragma once
// The names of the objects in haptex's HDF5 files, one home for each (schemas/hdf5-layout.md is
// the specification; `haptex qa` checks files against it). Code names an object through these,
// never by a string of its own.
namespace haptex::dataset::layout {

// Root attributes naming a file's inputs, beside the stamp every file carries (core/h5/file.hpp).
inline constexpr const char* kFieldMap = "field_map";                // recordings: the field map convert read with
inline constexpr const char* kRecordingsFile = "recordings_file";    // dataset: align's recordings file
inline constexpr const char* kRecordingsSha256 = "recordings_sha256";
inline constexpr const char* kGelsightFile = "gelsight_file";        // dataset: align's gelsight file
inline constexpr const char* kGelsightSha256 = "gelsight_sha256";

// Every file with materials: /materials/{material}/...
inline constexpr const char* kMaterials = "materials";
inline constexpr const char* kName = "name";  // attribute: the material's name as the source spells it
// Dataset file (align): the material's names in the two files it joined.
inline constexpr const char* kRecordingsName = "recordings_name";
inline constexpr const char* kGelsightName = "gelsight_name";

// Recordings file (convert), and the dataset's copy: /materials/{material}/recordings/{k}/...
inline constexpr const char* kRecordings = "recordings";
inline constexpr const char* kAccel = "accel";                        // DFT321, m/s^2
inline constexpr const char* kAccelXyz = "accel_xyz";                 // the three axes
inline constexpr const char* kForceNormal = "force_normal";           // N, unfiltered
inline constexpr const char* kForceNormalLp = "force_normal_lp";      // N, 20 Hz zero-phase low-passed
inline constexpr const char* kForceTangential = "force_tangential";   // N, optional
inline constexpr const char* kSpeed = "speed";                        // mm/s, unfiltered
inline constexpr const char* kSpeedLp = "speed_lp";                   // mm/s, low-passed
inline constexpr const char* kPosition = "position";                  // mm, optional
inline constexpr const char* kSampleRate = "sample_rate_hz";          // attribute of a recording
inline constexpr const char* kDuration = "duration_s";                // attribute of a recording
// A recording's attributes saying how its signals were made (convert's preprocessing).
inline constexpr const char* kLowpassFilterAttr = "lowpass_filter";
inline constexpr const char* kLowpassOrderAttr = "lowpass_order";
inline constexpr const char* kLowpassCutoffAttr = "lowpass_cutoff_hz";
inline constexpr const char* kLowpassMethodAttr = "lowpass_method";
inline constexpr const char* kAccelReduction = "accel_reduction";
inline constexpr const char* kAccelReductionWindow = "accel_reduction_window";
inline constexpr const char* kAccelReductionHop = "accel_reduction_hop";
inline constexpr const char* kHattTexture = "hatt_texture";          // the HaTT texture number, when from HaTT
inline constexpr const char* kSourceSha256 = "source_sha256";         // attribute: the source file's hash
// Attributes of a recording converted from the Cluster Haptic Texture Database (docs/convert.md):
// the take's conditions as its file name states them, and its force and position files.
inline constexpr const char* kClusterTexture = "cluster_texture";
inline constexpr const char* kStrokeDirection = "stroke_direction_deg";
inline constexpr const char* kCommandedSpeed = "commanded_speed_mm_s";
inline constexpr const char* kCommandedForce = "commanded_force_n";
inline constexpr const char* kRepeat = "repeat";
inline constexpr const char* kForceSourceFile = "force_source_file";
inline constexpr const char* kForceSourceSha256 = "force_source_sha256";
inline constexpr const char* kPositionSourceFile = "position_source_file";
inline constexpr const char* kPositionSourceSha256 = "position_source_sha256";

// Gelsight file (capture extract), and the dataset's copy: /materials/{material}/presses/{j}/...
inline constexpr const char* kPresses = "presses";
inline constexpr const char* kReference = "reference";        // no-contact frame
inline constexpr const char* kPeak = "peak";                  // the press's highest-scoring frame
inline constexpr const char* kPeakIndex = "peak_index";
inline constexpr const char* kFrames = "frames";              // the 12 frames around the peak
inline constexpr const char* kFrameIndices = "frame_indices";
inline constexpr const char* kContrast = "contrast";          // per-frame contact score
inline constexpr const char* kEncoding = "encoding";            // attribute of encoded images: "jpeg" or "png"
inline constexpr const char* kChannelOrder = "channel_order"; // attribute of a press and its images (dataset/channel_order.hpp)
// Attribute of press files and gelsight presses: the contact score of a no-contact frame, which the
// trigger is a multiple of (docs/capture.md, "Finding presses"); absent in files from before it.
inline constexpr const char* kNoContactLevel = "no_contact_level";
// Attributes of a gelsight press (dataset/gelsight_file.hpp); the press file's share some of them.
inline constexpr const char* kSourceFile = "source_file";
inline constexpr const char* kPressInSource = "press_in_source";
inline constexpr const char* kFrameStart = "frame_start";
inline constexpr const char* kFrameEnd = "frame_end";
inline constexpr const char* kSamples = "samples";            // also of a recording
inline constexpr const char* kContactFirst = "contact_first";
inline constexpr const char* kContactLast = "contact_last";
inline constexpr const char* kPeakScore = "peak_score";
inline constexpr const char* kWidth = "width";
inline constexpr const char* kHeight = "height";
inline constexpr const char* kFps = "fps";
inline constexpr const char* kReferenceSource = "reference_source";
inline constexpr const char* kScoreMethod = "score_method";
inline constexpr const char* kNoise = "noise";
inline constexpr const char* kPixelThreshold = "pixel_threshold";
inline constexpr const char* kTrigger = "trigger";
inline constexpr const char* kRelease = "release";
inline constexpr const char* kContactSheet = "contact_sheet";
// The SHA-256 of the press's contact sheet as written, by which --force knows an earlier sheet folder
// as the file's (capture extract).
inline constexpr const char* kContactSheetSha256 = "contact_sheet_sha256";
inline constexpr const char* kSourceFramesUnreadable = "source_frames_unreadable";

inline constexpr const char* kPressMaterial = "material";     // the press file's material name
// Press file (capture record; schemas/hdf5-layout.md "Press file"): root datasets and attributes
// beyond those a gelsight press shares (frames, reference, contrast, samples, encoding, width,
// height, fps, contact_first, contact_last, noise, pixel_threshold, trigger, no_contact_level).
inline constexpr const char* kTimestampNs = "timestamp_ns";
inline constexpr const char* kSequence = "sequence";
inline constexpr const char* kFlags = "flags";
inline constexpr const char* kPressMaterialId = "material_id";
inline constexpr const char* kPressIndex = "press_index";
inline constexpr const char* kDevice = "device";
inline constexpr const char* kCard = "card";
inline constexpr const char* kDriver = "driver";
inline constexpr const char* kBusInfo = "bus_info";
inline constexpr const char* kSerial = "serial";
inline constexpr const char* kFourcc = "fourcc";
inline constexpr const char* kRequestedFps = "requested_fps";
inline constexpr const char* kLockedControls = "locked_controls";
inline constexpr const char* kMissingControls = "missing_controls";
inline constexpr const char* kDroppedFrames = "dropped_frames";
inline constexpr const char* kErrorFrames = "error_frames";
inline constexpr const char* kCorruptFrames = "corrupt_frames";
inline constexpr const char* kPeakFrame = "peak_frame";
inline constexpr const char* kEndedBy = "ended_by";

// Attributes of any dataset haptex writes: what its values mean.
inline constexpr const char* kUnits = "units";
inline constexpr const char* kDescription = "description";

// Dataset file (align): the model's windows, /windows/...
inline constexpr const char* kWindows = "windows";
inline constexpr const char* kWindowMaterials = "materials";  // material ids, indexed by kWindowMaterial
inline constexpr const char* kWindowMaterial = "material";
inline constexpr const char* kWindowRecording = "recording";
inline constexpr const char* kWindowStart = "start";
inline constexpr const char* kWindowAction = "action";
inline constexpr const char* kWindowTarget = "target";
inline constexpr const char* kStride = "stride";                    // attributes of /windows
inline constexpr const char* kActionSamplesAttr = "action_samples";
inline constexpr const char* kWindowSamplesAttr = "window_samples";
inline constexpr const char* kActionEndAttr = "action_end";
inline constexpr const char* kActionStepAttr = "action_step";

// Merged files (haptex merge): /shards/{s}/..., one group per input in command-line order, holding
// the input's stamp and root attributes as they were, and these.
inline constexpr const char* kShards = "shards";
inline constexpr const char* kShardFile = "file";            // the input's path as given
inline constexpr const char* kShardSha256 = "sha256";        // the SHA-256 of its bytes
inline constexpr const char* kShardMaterials = "materials";  // the material ids taken from it, space-separated
inline constexpr const char* kShardLeftOut = "left_out";     // its material ids --keep-first left out, space-separated

// Files made from a dataset and its split (model, windows): the inputs' SHA-256, root attributes.
inline constexpr const char* kDatasetSha256 = "dataset_sha256";
inline constexpr const char* kSplitSha256 = "split_sha256";
inline constexpr const char* kDatasetFile = "dataset_file";
inline constexpr const char* kSplitFile = "split_file";

// Windows file (haptex windows): the evaluation's grid, /windows/... as in the dataset file plus
// which test section each window lies in and the material's test press.
inline constexpr const char* kWindowSection = "section";
inline constexpr const char* kWindowPress = "press";

// Predictions file (another method's predictions for `haptex evaluate --predictions`; users write it,
// python/haptex_data.py's write_predictions for one): /spectra, optional /signals/{k}, timings.
inline constexpr const char* kPredictedSpectra = "spectra";
inline constexpr const char* kPredictedSignals = "signals";
inline constexpr const char* kQuerySeconds = "query_seconds";    // root attribute
inline constexpr const char* kSignalSeconds = "seconds";         // attribute of /signals
inline constexpr const char* kPredictionsSource = "source";      // root attribute: the method, one line
// Its format mark: not haptex_format, since haptex never writes a predictions file, so `--force` of a
// haptex command never replaces one (docs/architecture.md, "Formats").
inline constexpr const char* kPredictionsFormatAttribute = "predictions_format";
inline constexpr const char* kPredictionsFormat = "predictions/1";

// Model file (predict/model_file.cpp; schemas/hdf5-layout.md, "Model file"): root attributes, the
// materials it knows (/materials/ids, /materials/names), the descriptor's spec, the normalisation,
// and the networks, each /layers/{i} with weight, bias and activation.
inline constexpr const char* kModelVariant = "variant";
inline constexpr const char* kModelConfig = "config";
inline constexpr const char* kModelMetrics = "metrics";
// The model's training log, its path relative to the model's folder (core/output_set.hpp,
// relative_to_folder_of), and the log's SHA-256 as written: --force over the model retires that log
// with it while it is still those bytes.
inline constexpr const char* kTrainingLogAttribute = "training_log";
inline constexpr const char* kTrainingLogSha256Attribute = "training_log_sha256";
inline constexpr const char* kMaterialIds = "ids";
inline constexpr const char* kMaterialNames = "names";
inline constexpr const char* kFeatureSpec = "feature_spec";
inline constexpr const char* kDescriptorSpec = "descriptor";
inline constexpr const char* kDescriptorSize = "size";
inline constexpr const char* kRadialBins = "radial_bins";
inline constexpr const char* kOrientations = "orientations";
inline constexpr const char* kOctaves = "octaves";
inline constexpr const char* kGradientScales = "gradient_scales";
inline constexpr const char* kDescriptorLength = "length";
inline constexpr const char* kNormalisation = "normalisation";
inline constexpr const char* kActionMean = "action_mean";
inline constexpr const char* kActionScale = "action_scale";
inline constexpr const char* kTargetScale = "target_scale";
inline constexpr const char* kForceMin = "force_min";
inline constexpr const char* kForceMax = "force_max";
inline constexpr const char* kSpeedMin = "speed_min";
inline constexpr const char* kSpeedMax = "speed_max";
inline constexpr const char* kDescriptorMean = "descriptor_mean";
inline constexpr const char* kDescriptorScale = "descriptor_scale";
inline constexpr const char* kTextureEncoder = "texture_encoder";
inline constexpr const char* kClassifier = "classifier";
inline constexpr const char* kMaterialLatents = "material_latents";
inline constexpr const char* kNets = "nets";
inline constexpr const char* kActionEncoder = "action_encoder";
inline constexpr const char* kPredictor = "predictor";
inline constexpr const char* kLayers = "layers";
inline constexpr const char* kWeight = "weight";
inline constexpr const char* kBias = "bias";
inline constexpr const char* kActivation = "activation";

}  // namespace haptex::dataset::layout
