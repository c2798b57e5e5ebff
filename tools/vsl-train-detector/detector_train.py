"""The training loop: random augmented batches, AdamW with a linear warm-up and a cosine decay,
checkpoints, a status line, and the held-out evaluation that sets the thresholds."""
import math
import random
import sys
import time

import numpy as np
import torch

import detector_data as data
from detector_eval import cross_validated_thresholds, detect
from detector_model import checkpoint
from detector_refiner import refine
from detector_targets import build_targets, decode_boxes, focal_loss, giou_loss

GIOU_WEIGHT = 5.0  # TTFNet's balance of the box loss against the centre-ness loss


def make_batch(real, sim, args, rng, stride):
    images, heats, boxes, weights = [], [], [], []
    out_h, out_w = args.input_h // stride, args.input_w // stride
    for _ in range(args.batch):
        use_sim = sim and (not real or rng.random() < args.sim_fraction)
        sample = rng.choice(sim if use_sim else real)
        image, b, c = data.augment(sample, args.input_w, args.input_h, rng)
        heat, box_target, weight = build_targets(b, c, len(data.CLASSES), out_h, out_w, stride,
                                                 len(data.CLASSES) if args.box_per_class else 1)
        images.append(data.to_tensor_layout(image))
        heats.append(heat)
        boxes.append(box_target)
        weights.append(weight)
    as_tensor = lambda xs: torch.from_numpy(np.stack(xs))
    return as_tensor(images), as_tensor(heats), as_tensor(boxes), as_tensor(weights)


def learning_rate(step, args):
    warmup = min(500, args.iterations // 10)
    if step < warmup:
        return args.lr * (step + 1) / warmup
    progress = (step - warmup) / max(1, args.iterations - warmup)
    return args.lr * (0.02 + 0.98 * 0.5 * (1 + math.cos(math.pi * progress)))


def train(net, real, sim, args, stride, checkpoint_path, log, monitor=None):
    """monitor(step): called every 2000 steps (held-out figures in the log; nothing is chosen on them)."""
    rng = random.Random(args.seed)
    optimizer = torch.optim.AdamW(net.parameters(), lr=args.lr, weight_decay=1e-4)
    num_classes = len(data.CLASSES)
    started = last_report = time.time()
    smoothed = None
    interactive = sys.stderr.isatty()
    net.train()
    steps = min(args.iterations, args.stop_after or args.iterations)
    for step in range(steps):
        for group in optimizer.param_groups:
            group["lr"] = learning_rate(step, args)
        images, heat, box_target, weight = make_batch(real, sim, args, rng, stride)
        maps = net(images)
        loss_centre = focal_loss(maps[:, :num_classes], heat)
        loss_box = giou_loss(decode_boxes(maps[:, num_classes:], stride), box_target, weight)
        loss = loss_centre + GIOU_WEIGHT * loss_box
        optimizer.zero_grad()
        loss.backward()
        torch.nn.utils.clip_grad_norm_(net.parameters(), 10.0)
        optimizer.step()
        value = float(loss)
        smoothed = value if smoothed is None else 0.98 * smoothed + 0.02 * value
        now = time.time()
        if (step + 1) % 1000 == 0 or step + 1 == steps:
            torch.save(checkpoint(net, step=step + 1), checkpoint_path)
        if monitor and (step + 1) % 2000 == 0 and step + 1 < steps:
            net.eval()
            log(monitor(step + 1))
            net.train()
        if now - last_report > (1 if interactive else 60) or step + 1 == steps:
            rate = (step + 1) / (now - started)
            left = (steps - step - 1) / rate
            log_line = (f"step {step + 1}/{steps}  loss {smoothed:.3f} (centre {float(loss_centre):.3f}, "
                        f"box {float(loss_box):.3f})  {rate:.2f} steps/s  {left / 60:.0f} min left")
            if interactive:
                sys.stderr.write("\r" + log_line + "\033[K")
                sys.stderr.flush()
            else:
                log(log_line)
            last_report = now
    if interactive:
        sys.stderr.write("\n")
    net.eval()


def evaluate(net, samples, args, stride, refiner=None):
    """Detections on the held-out images (letterboxed to the input as the C++ detector does; with a
    box refiner, its classes' boxes measured again), and per class the 2-fold cross-validated
    thresholds and figures (detector_eval.py)."""
    net.eval()
    detections, truths = [], []
    for sample in samples:
        image = sample.load()
        boxed, scale = data.letterbox(image, args.input_w, args.input_h)
        found = detect(net, torch.from_numpy(data.to_tensor_layout(boxed))[None], stride)[0]
        found = [(c, s, x0 / scale, y0 / scale, x1 / scale, y1 / scale) for c, s, x0, y0, x1, y1 in found]
        detections.append(refine(refiner, image, found))
        truths.append((data.pixel_boxes(sample), sample.classes))
        sample.image = None
    return cross_validated_thresholds(detections, truths, len(data.CLASSES))
