// Class-specific recognizers from model files (config/recognition/<type>.yaml). One file per
// class:
//
//   recognizer: door              # the implementation: door | handle
//   type: door                    # the world-model object type it reports
//   provenance: "..."             # free text: how the model was made
//   model:                        # the Gaussian class model (class_model.hpp)
//     descriptor: [chord_ratio_major, ...]
//     mean: [...]
//     covariance: [[...], ...]
//     max_mahalanobis2: 18.5
//   parameters: {...}             # the implementation's own (door_recognizer.hpp,
//                                 # handle_recognizer.hpp); every key optional
//
// Errors in a file are config::Error, one line "file:line: key: what".
#pragma once

#include <Eigen/Core>

#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "vsl/recognition/class_model.hpp"
#include "vsl/recognition/class_recognizer.hpp"
#include "vsl/recognition/door_recognizer.hpp"
#include "vsl/recognition/handle_recognizer.hpp"

namespace vsl::config {
class Node;
}

namespace vsl::recognition {

// The whole content of one model file.
struct RecognizerFile {
  std::string recognizer = "door";    // "door" or "handle"
  GaussianClassModel model;           // its type and provenance are the file's
  DoorRecognizerParameters door;      // used when recognizer == "door"
  HandleRecognizerParameters handle;  // used when recognizer == "handle"
};

// The implementations' names and their descriptors' component names (throws
// std::invalid_argument for an unknown implementation).
const std::vector<std::string>& recognizer_names();
const std::vector<std::string>& descriptor_names_of(const std::string& recognizer);
// Fit options suited to the implementation's descriptor (per-component standard deviation floors,
// acceptance probability 0.99), for training tools.
ClassModelFitOptions default_fit_options(const std::string& recognizer);
// The descriptor the file's recognizer computes for `blob` (what a training tool collects).
Eigen::VectorXd descriptor_of(const RecognizerFile& file, const Blob& blob);

RecognizerFile recognizer_file_from(const config::Node& root);
RecognizerFile read_recognizer_file(const std::string& path);
void write_recognizer_file(std::ostream& out, const RecognizerFile& file);
// Writes the file (replacing it); throws std::runtime_error when it cannot be written.
void save_recognizer_file(const RecognizerFile& file, const std::string& path);

std::unique_ptr<ClassRecognizer> make_recognizer(const RecognizerFile& file);
std::unique_ptr<ClassRecognizer> load_recognizer(const std::string& model_file);
// One recognizer per file; two files of the same type are an error (config::Error naming the
// second file), since the pipeline would report every object twice.
std::vector<std::unique_ptr<ClassRecognizer>> load_recognizers(
    const std::vector<std::string>& model_files);

}  // namespace vsl::recognition
