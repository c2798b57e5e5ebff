// vsl-make-dataset: labelled training images of a world as the simulated head sees it
// (docs/dataset.md).
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "dataset_files.hpp"
#include "dataset_options.hpp"
#include "dataset_run.hpp"
#include "vsl/config/node.hpp"

int main(int argc, char** argv) {
  using namespace vsl::tools;
  try {
    const std::optional<DatasetOptions> options =
        parse_dataset_options(std::vector<std::string>(argv + 1, argv + argc));
    if (!options) {
      std::cout << dataset_usage();
      return 0;
    }
    run_dataset(*options);
  } catch (const UsageError& e) {
    std::cerr << "vsl-make-dataset: " << e.what() << " (see vsl-make-dataset --help)\n";
    return 2;
  } catch (const vsl::config::Error& e) {
    std::cerr << e.what() << "\n";
    return 2;
  } catch (const IoError& e) {
    std::cerr << "vsl-make-dataset: " << e.what() << "\n";
    return 1;
  } catch (const std::invalid_argument& e) {  // the renderer's: an unusable head calibration
    std::cerr << "vsl-make-dataset: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "vsl-make-dataset: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
