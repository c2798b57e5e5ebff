"""The box refiner (for handles): a second stage that looks again at each handle the detector
finds, in a crop of the image at the image's own resolution, measures its box again and says
whether it is a handle at all.

Why: the detector sees a 640 x 480 image at 448 x 352, and a handle there is a few output cells
across. Its boxes regress to the mean size: on the held-out photographs a handle under 5 px
across at the input came out 1.75 times too thick, one over 20 px 0.8 times, and only 40 % of the
handles it found got a box of IoU >= 0.5 (median 0.45); 43 % of its false handles at recall 0.3
were on plain background. The refiner sees each handle box in a crop of twice its size, scaled
to CROP x CROP pixels whatever the handle's size and aspect (each axis by its own factor).

Crop geometry (the C++ detector, libs/recognition/src/box_refiner.cpp, crops the same way): a
box (x0, y0, x1, y1) in image pixels (continuous; pixel k covers [k, k + 1)) gives the window of
width W = max(CONTEXT (x1 - x0), MIN_SIDE_PX) and height H likewise, centred on the box. Crop
pixel i covers image x in [wx + i W / CROP, wx + (i + 1) W / CROP), sampled bilinearly at its
centre, the image's edge pixels repeated outside it. The network's five outputs are the box's
sides as fractions of the window, x0 = wx + t0 W, y0 = wy + t1 H, x1 = wx + t2 W, y1 = wy + t3 H,
and the logit l of "a handle is in this box"; the detection's confidence becomes the geometric
mean sqrt(c sigmoid(l)) of the detector's centre-ness c and that probability. An untrained
refiner returns the window's middle half (t = 0.25, 0.25, 0.75, 0.75: the box itself when it is
at least MIN_SIDE_PX / CONTEXT wide and high) and probability 0.5.

Training examples: every labelled handle of the training images, cropped around the detector's
own boxes on it (IoU >= 0.2) and around boxes jittered from the label (centre by 15 % of the size,
each side's length by a log-normal factor of sigma 0.3: the detector's errors measured on the
photographs); and as many of the detector's boxes that are on no handle (IoU < 0.1, confidence
>= 0.05). The loss is 1 - GIoU of the refined box plus a smooth L1 on the four fractions on the
handles, and half the binary cross-entropy of the logit on all. Rendered images make up
--refiner-sim-fraction (a fifth) of each batch: with nine renders' handles to each photograph's,
the refiner learned the renders' exact silhouettes and moved the photographs' boxes away from
their labels; with two fifths, the photographs' handle precision at recall 0.3 fell from 0.57 to
0.49; with a fifth it scores many rendered handles low (docs/learned-detector.md).
"""
import math
import random
import sys
import time

import cv2
import numpy as np
import torch
from torch import nn
import torch.nn.functional as F

import detector_data as data
from detector_eval import detect, iou
from detector_model import conv_bn

CROP = 32
CONTEXT = 2.0
MIN_SIDE_PX = 16.0
REFINED_CLASSES = ("handle",)
# The refiner looks at the MAX_BOXES strongest candidates of a class in an image (by centre-ness)
# and drops the rest: a crop costs 0.1 ms on one core, so this bounds the refiner's time (a
# kitchen view holds up to 30 handle candidates; a photograph a median of 2).
MAX_BOXES = 32
MAX_SIM_IMAGES = 1500  # rendered images the examples are collected from (many handles each)


class BoxRefiner(nn.Module):
    """CROP x CROP RGB in [0, 1] -> the box's four sides as fractions of the crop window, and the
    logit of a handle being in the box. A full 3x3 convolution, then depthwise-separable ones
    down to stride 8 (four plain 3x3 convolutions to stride 8 cost half as much in OpenCV, and
    left held-out handle precision at recall 0.3 at 0.48 instead of 0.59)."""

    def __init__(self):
        super().__init__()

        def separable(cin, cout, stride):
            return nn.Sequential(conv_bn(cin, cin, 3, stride, groups=cin), conv_bn(cin, cout, 1))

        self.body = nn.Sequential(conv_bn(3, 16, 3, 1), separable(16, 32, 2), separable(32, 64, 2),
                                  separable(64, 64, 2))
        self.sides = nn.Linear(64 * (CROP // 8) ** 2, 5)
        nn.init.zeros_(self.sides.weight)
        with torch.no_grad():
            self.sides.bias.copy_(torch.tensor([0.25, 0.25, 0.75, 0.75, 0.0]))

    def forward(self, x):
        return self.sides(self.body(x).flatten(1))


def crop_window(box):
    """(wx, wy, W, H) in image pixels around box (x0, y0, x1, y1)."""
    x0, y0, x1, y1 = box
    w = max(CONTEXT * (x1 - x0), MIN_SIDE_PX)
    h = max(CONTEXT * (y1 - y0), MIN_SIDE_PX)
    return (x0 + x1 - w) / 2, (y0 + y1 - h) / 2, w, h


def crop(image, window):
    wx, wy, ww, wh = window
    sx, sy = CROP / ww, CROP / wh
    # OpenCV indexes pixel centres: crop index i = sx (k + 0.5 - wx) - 0.5 for image index k.
    m = np.array([[sx, 0, sx * (0.5 - wx) - 0.5], [0, sy, sy * (0.5 - wy) - 0.5]], np.float32)
    return cv2.warpAffine(image, m, (CROP, CROP), flags=cv2.INTER_LINEAR, borderMode=cv2.BORDER_REPLICATE)


def to_window(box, window):
    wx, wy, ww, wh = window
    return np.array([(box[0] - wx) / ww, (box[1] - wy) / wh, (box[2] - wx) / ww, (box[3] - wy) / wh], np.float32)


def from_window(t, window):
    wx, wy, ww, wh = window
    return (wx + t[0] * ww, wy + t[1] * wh, wx + t[2] * ww, wy + t[3] * wh)


def to_input(crops):
    return torch.from_numpy(np.stack([data.to_tensor_layout(c) for c in crops]))


def refine(refiner, image, detections):
    """Detections (class, score, x0, y0, x1, y1) in image pixels -> the same with the refined
    classes' boxes measured again in crops of `image` and their scores sqrt(score p); of each
    refined class the MAX_BOXES strongest, the others dropped."""
    if refiner is None:
        return detections
    out = [d for d in detections if data.CLASSES[d[0]] not in REFINED_CLASSES]
    for name in REFINED_CLASSES:
        cls = data.CLASSES.index(name)
        chosen = sorted((d for d in detections if d[0] == cls), key=lambda d: -d[1])[:MAX_BOXES]
        if not chosen:
            continue
        windows = [crop_window(d[2:]) for d in chosen]
        with torch.no_grad():
            outputs = refiner(to_input([crop(image, w) for w in windows])).numpy()
        for d, o, w in zip(chosen, outputs, windows):
            probability = 1.0 / (1.0 + math.exp(-float(o[4])))
            out.append((cls, math.sqrt(d[1] * probability), *from_window(o[:4], w)))
    return out


def collect_examples(detector, samples, input_w, input_h, stride, log):
    """Handles: (sample, box to crop around or None, labelled box) for every labelled handle of the
    samples, None standing for a box jittered from the label, drawn anew each time, and the
    detector's own boxes on a handle (IoU >= 0.2) once each. Not handles: (sample, box) for the
    detector's handle boxes on no labelled handle."""
    handle = data.CLASSES.index("handle")
    handles, others = [], []
    started = time.time()
    detector.eval()
    for n, sample in enumerate(samples):
        image = sample.load()
        labels = data.pixel_boxes(sample)[sample.classes == handle]
        boxed, scale = data.letterbox(image, input_w, input_h)
        found = detect(detector, torch.from_numpy(data.to_tensor_layout(boxed))[None], stride, min_score=0.05)[0]
        count = len(handles) + len(others)
        for c, _, *box in found:
            if c != handle:
                continue
            box = np.array(box) / scale
            overlaps = iou(box, labels) if len(labels) else np.zeros(1)
            k = int(np.argmax(overlaps))
            if overlaps[k] >= 0.2:
                handles.append((sample, box, labels[k]))
            elif overlaps[k] < 0.1:
                others.append((sample, box))
        handles += [(sample, None, label) for label in labels]
        if len(handles) + len(others) == count:
            sample.image = None  # nothing to crop from it: not kept in memory
        if time.time() - started > 60 and n % 200 == 0:
            log(f"refiner examples: image {n + 1} of {len(samples)}")
    return handles, others


def _jittered(label, rng):
    w, h = label[2] - label[0], label[3] - label[1]
    cx = (label[0] + label[2]) / 2 + rng.gauss(0, 0.15) * w
    cy = (label[1] + label[3]) / 2 + rng.gauss(0, 0.15) * h
    w *= math.exp(rng.gauss(0.05, 0.3))
    h *= math.exp(rng.gauss(0.05, 0.3))
    return (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)


def _training_example(example, rng):
    """A crop and its targets: the box's sides in the window (the box itself for a non-handle,
    not used) and 1 for a handle, 0 for not one."""
    if len(example) == 2:
        sample, box = example
        label, is_handle = box, 0.0
    else:
        sample, box, label = example
        is_handle = 1.0
        if box is None or rng.random() < 0.3:
            box = _jittered(label, rng)
    window = crop_window(box)
    image, target = crop(sample.load(), window), to_window(label, window)
    # A handle is a handle mirrored or turned by 90 degrees: flip x, transpose, or both.
    turn = rng.randrange(4)
    if turn & 1:
        image, target = image[:, ::-1], np.array([1 - target[2], target[1], 1 - target[0], target[3]], np.float32)
    if turn & 2:
        image, target = image.transpose(1, 0, 2), target[[1, 0, 3, 2]]
    return data.jitter_colours(np.ascontiguousarray(image), rng), target, is_handle


def _giou(p, t):
    iw = (torch.min(p[:, 2], t[:, 2]) - torch.max(p[:, 0], t[:, 0])).clamp(min=0)
    ih = (torch.min(p[:, 3], t[:, 3]) - torch.max(p[:, 1], t[:, 1])).clamp(min=0)
    inter = iw * ih
    area_p = (p[:, 2] - p[:, 0]).clamp(min=1e-4) * (p[:, 3] - p[:, 1]).clamp(min=1e-4)
    area_t = (t[:, 2] - t[:, 0]) * (t[:, 3] - t[:, 1])
    union = area_p + area_t - inter
    enclosing = (torch.max(p[:, 2], t[:, 2]) - torch.min(p[:, 0], t[:, 0])) * \
        (torch.max(p[:, 3], t[:, 3]) - torch.min(p[:, 1], t[:, 1]))
    return inter / union.clamp(min=1e-6) - (enclosing - union) / enclosing.clamp(min=1e-6)


def train_refiner(refiner, real_examples, sim_examples, sim_fraction, steps, lr, seed, log, batch=128):
    """real_examples, sim_examples: collect_examples' (handles, others) of photographs (or a
    user's images) and of renders. Each batch: half handles, half other boxes, sim_fraction of
    both from renders; AdamW with a cosine decay; a status line every minute (or second on a
    terminal)."""
    if not real_examples[0] and not sim_examples[0]:
        raise data.DataError("the box refiner has no labelled handle to learn from")
    rng = random.Random(seed)
    optimizer = torch.optim.AdamW(refiner.parameters(), lr=lr, weight_decay=1e-4)
    interactive = sys.stderr.isatty()
    started = last = time.time()
    refiner.train()

    def draw(kind):
        rendered = sim_examples[kind] and (not real_examples[kind] or rng.random() < sim_fraction)
        return rng.choice(sim_examples[kind] if rendered else real_examples[kind])

    others = bool(real_examples[1] or sim_examples[1])
    for step in range(steps):
        for group in optimizer.param_groups:
            group["lr"] = lr * 0.5 * (1 + math.cos(math.pi * step / steps))
        examples = [_training_example(draw(1 if others and n % 2 else 0), rng) for n in range(batch)]
        outputs = refiner(to_input([e[0] for e in examples]))
        target = torch.from_numpy(np.stack([e[1] for e in examples]))
        is_handle = torch.tensor([e[2] for e in examples])
        handles = is_handle > 0.5
        sides = outputs[handles, :4]
        loss = (1 - _giou(sides, target[handles])).mean() + \
            F.smooth_l1_loss(sides, target[handles], beta=0.05) + \
            0.5 * F.binary_cross_entropy_with_logits(outputs[:, 4], is_handle)
        optimizer.zero_grad()
        loss.backward()
        optimizer.step()
        now = time.time()
        if now - last > (1 if interactive else 60) or step + 1 == steps:
            line = f"refiner step {step + 1}/{steps}  loss {float(loss):.3f}  {(step + 1) / (now - started):.1f} steps/s"
            if interactive:
                sys.stderr.write("\r" + line + "\033[K" + ("\n" if step + 1 == steps else ""))
                sys.stderr.flush()
            else:
                log(line)
            last = now
    refiner.eval()


def refiner_checkpoint(refiner):
    return {"weights": refiner.state_dict(), "crop": CROP, "classes": list(REFINED_CLASSES)}


def load_refiner(path):
    state = torch.load(path, map_location="cpu")
    if state.get("crop") != CROP:
        raise data.DataError(f"{path}: a refiner of {state.get('crop')} px crops, this tool trains {CROP} px ones")
    refiner = BoxRefiner()
    try:
        refiner.load_state_dict(state["weights"])
    except RuntimeError as e:
        raise data.DataError(f"{path}: not a box refiner of this tool's shape "
                             f"({str(e).splitlines()[-1].strip()})")
    return refiner.eval()
