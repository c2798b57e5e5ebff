// Model files -> class-specific recognizers (recognizer_factory.hpp).
#include "vsl/recognition/recognizer_factory.hpp"

#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>

#include "vsl/config/node.hpp"
#include "vsl/recognition/descriptors.hpp"

namespace vsl::recognition {
namespace {

const std::string kDoor = "door";
const std::string kHandle = "handle";

// YAML double-quoted scalar of free text (provenance): escape backslashes and quotes, one line.
std::string quoted(const std::string& text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (c == '\n' || c == '\r') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out + "\"";
}

}  // namespace

const std::vector<std::string>& recognizer_names() {
  static const std::vector<std::string> names{kDoor, kHandle};
  return names;
}

const std::vector<std::string>& descriptor_names_of(const std::string& recognizer) {
  if (recognizer == kDoor) return door_descriptor_names();
  if (recognizer == kHandle) return handle_descriptor_names();
  throw std::invalid_argument("unknown recognizer '" + recognizer + "' (door or handle)");
}

ClassModelFitOptions default_fit_options(const std::string& recognizer) {
  ClassModelFitOptions options;
  if (recognizer == kDoor) {
    // Chord ratios and elasticity: 0.03 (pixel quantization of a 30 px blob); angles: 1 degree;
    // log aspect: 0.03; colour angle: 0.01 rad (sensor noise on a mean colour).
    options.min_stddev = {0.03, 0.03, 0.03, 0.0175, 0.0175, 0.03, 0.01};
  } else if (recognizer == kHandle) {
    // log ratio 0.05; colour angle 0.01 rad; colour distance 0.01.
    options.min_stddev = {0.05, 0.01, 0.01};
  } else {
    descriptor_names_of(recognizer);  // throws
  }
  return options;
}

Eigen::VectorXd descriptor_of(const RecognizerFile& file, const Blob& blob) {
  if (file.recognizer == kDoor) return door_descriptor(blob, file.door.ideal_colour_rgb);
  if (file.recognizer == kHandle) return handle_descriptor(blob, file.handle.ideal_colour_rgb);
  descriptor_names_of(file.recognizer);  // throws
  return {};
}

RecognizerFile recognizer_file_from(const config::Node& root) {
  root.expect_map();
  root.expect_keys({"recognizer", "type", "provenance", "model", "parameters"});
  RecognizerFile out;
  const config::Node recognizer = root.at("recognizer");
  out.recognizer = recognizer.as_string();
  if (out.recognizer != kDoor && out.recognizer != kHandle) {
    recognizer.fail("unknown recognizer '" + out.recognizer + "' (door or handle)");
  }
  const std::string type = root.at("type").as_string();
  const std::string provenance = root.get("provenance", "");
  out.model =
      class_model_from(root.at("model"), type, provenance, descriptor_names_of(out.recognizer));
  const std::optional<config::Node> parameters = root.find("parameters");
  if (out.recognizer == kDoor) {
    if (parameters) out.door = door_parameters_from(*parameters);
  } else {
    if (parameters) out.handle = handle_parameters_from(*parameters);
  }
  return out;
}

RecognizerFile read_recognizer_file(const std::string& path) {
  return recognizer_file_from(config::Node::load_file(path));
}

void write_recognizer_file(std::ostream& out, const RecognizerFile& file) {
  descriptor_names_of(file.recognizer);  // throws for an unknown implementation
  out << "# Class model of the " << file.recognizer
      << " recognizer (paper §2.1; format: libs/recognition/include/vsl/recognition/"
         "recognizer_factory.hpp).\n"
      << "# Descriptor components: libs/recognition/include/vsl/recognition/descriptors.hpp.\n"
      << "recognizer: " << file.recognizer << "\n"
      << "type: " << file.model.type() << "\n"
      << "provenance: " << quoted(file.model.provenance()) << "\n"
      << "model:\n";
  write_class_model(out, file.model, "  ");
  out << "parameters:\n";
  if (file.recognizer == kDoor) {
    write_door_parameters(out, file.door, "  ");
  } else {
    write_handle_parameters(out, file.handle, "  ");
  }
}

void save_recognizer_file(const RecognizerFile& file, const std::string& path) {
  std::ostringstream text;
  write_recognizer_file(text, file);
  std::ofstream out(path, std::ios::trunc);
  out << text.str();
  out.close();
  if (!out) throw std::runtime_error(path + ": cannot write the model file");
}

std::unique_ptr<ClassRecognizer> make_recognizer(const RecognizerFile& file) {
  if (file.recognizer == kDoor) return std::make_unique<DoorRecognizer>(file.model, file.door);
  if (file.recognizer == kHandle) {
    return std::make_unique<HandleRecognizer>(file.model, file.handle);
  }
  descriptor_names_of(file.recognizer);  // throws
  return nullptr;
}

std::unique_ptr<ClassRecognizer> load_recognizer(const std::string& model_file) {
  return make_recognizer(read_recognizer_file(model_file));
}

std::vector<std::unique_ptr<ClassRecognizer>> load_recognizers(
    const std::vector<std::string>& model_files) {
  std::vector<std::unique_ptr<ClassRecognizer>> out;
  std::vector<std::string> sources;
  for (const std::string& path : model_files) {
    const config::Node root = config::Node::load_file(path);
    RecognizerFile file = recognizer_file_from(root);
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (out[i]->type() == file.model.type()) {
        root.at("type").fail("type '" + file.model.type() + "' is already recognized by " +
                             sources[i]);
      }
    }
    out.push_back(make_recognizer(file));
    sources.push_back(path);
  }
  return out;
}

}  // namespace vsl::recognition
