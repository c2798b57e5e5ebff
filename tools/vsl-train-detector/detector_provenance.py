"""The model's description file (door_handle.yaml): what the C++ detector needs to run it (input
size, stride, classes, thresholds) and where it came from (data, seed, command, figures)."""
import os

import detector_data as data
import detector_refiner


def write_description(path, args, figures, command, refined, counts, seconds, date):
    thresholds = {c: (f["threshold"] if figures else 0.3) for c, f in zip(data.CLASSES, figures or [{}] * 2)}
    lines = [
        "# The learned door and handle detector (libs/recognition/include/vsl/recognition/learned_detector.hpp),",
        "# written by tools/vsl-train-detector. Paths are relative to this file.",
        "detector:",
        "  model: door_handle.onnx",
        f"  input_width: {args.input_w}",
        f"  input_height: {args.input_h}",
        "  stride: 4",
        f"  classes: [{', '.join(data.CLASSES)}]",
        "  # Per class, the confidence maximizing F1 on the held-out images (2-fold cross-validated below).",
        "  min_confidence: {" + ", ".join(f"{c}: {t:.3f}" for c, t in thresholds.items()) + "}",
    ]
    if refined:
        lines += [
            "  # A second network measures and scores these classes' boxes again from crops of the image",
            "  # (tools/vsl-train-detector/detector_refiner.py).",
            "  refiner:",
            "    model: box_refiner.onnx",
            f"    classes: [{', '.join(detector_refiner.REFINED_CLASSES)}]",
            f"    crop_px: {detector_refiner.CROP}",
            f"    context: {detector_refiner.CONTEXT}",
            f"    min_side_px: {detector_refiner.MIN_SIDE_PX:g}",
            f"    max_boxes: {detector_refiner.MAX_BOXES}",
        ]
    lines += [
        "provenance:",
        f"  command: \"{command}\"",
        f"  date: {date}",
        f"  seed: {args.seed}",
        f"  split_seed: {args.split_seed}",
        f"  init: \"{os.path.basename(args.init) if args.init else 'random'}\"",
        "  # The network (detector_model.py): the stride-16 and stride-32 stages' channels and blocks,",
        "  # and whether each class regresses its own box.",
        f"  architecture: {{deep: [{args.deep[0]}, {args.deep[1]}], deep_blocks: [{args.deep_blocks[0]}, "
        f"{args.deep_blocks[1]}], box_per_class: {str(args.box_per_class).lower()}}}",
        f"  iterations: {args.iterations}" + (f"  # stopped after {args.stop_after}" if args.stop_after else ""),
        f"  refiner_steps: {args.refiner_steps}",
        f"  batch: {args.batch}",
        f"  training_minutes: {seconds / 60:.1f}",
        f"  threads: {args.threads}",
        f"  images: {{real_or_own: {counts['real']}, rendered: {counts['rendered']}, held_out: {counts['held_out']}}}",
        "  data: [" + ", ".join(f"\"{os.path.basename(os.path.normpath(d))}\"" for d in args.labels + args.real + args.sim) + "]",
    ]
    if figures:
        lines.append("  # Held-out images: AP50 (PASCAL VOC, IoU >= 0.5), and precision and recall at a threshold")
        lines.append("  # chosen on the other half of them (2-fold).")
        lines.append("  held_out:")
        for c, f in zip(data.CLASSES, figures):
            lines.append(f"    {c}: {{ap50: {f['ap50']:.3f}, precision: {f['cv_precision']:.3f}, "
                         f"recall: {f['cv_recall']:.3f}, objects: {f['objects']}}}")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")
