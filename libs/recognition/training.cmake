# Training and evaluation labels (helper "train"): labels from the simulator's id buffer and
# ground truth for evaluation (labelling), hand-labelled boxes for a user's own images
# (box_labels). Used by tools/vsl-train-recognition and tools/vsl-eval-recognition.
list(APPEND VSL_RECOGNITION_SOURCES
  ${CMAKE_CURRENT_SOURCE_DIR}/src/labelling.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/src/box_labels.cpp)
list(APPEND VSL_RECOGNITION_TESTS
  ${CMAKE_CURRENT_SOURCE_DIR}/test/labelling_test.cpp
  ${CMAKE_CURRENT_SOURCE_DIR}/test/box_labels_test.cpp)
