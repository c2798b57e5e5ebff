"""Labelled images for the detector: YOLO folders (images/, labels/) and the project's box-label
YAML (vsl/recognition/box_labels.hpp), read into one list of samples; training augmentation."""
import math
import os
import random

import cv2
import numpy as np
import yaml

CLASSES = ("door", "handle")
IMAGE_SUFFIXES = (".jpg", ".jpeg", ".png", ".bmp")
# World-model and label types of the project's box labels -> detector class.
TYPE_CLASS = {"door": 0, "room_door": 0, "drawer_front": 0, "fridge_door": 0, "handle": 1}


class DataError(Exception):
    pass


class Sample:
    """One labelled image: its path, boxes (N x 4 pixels, x0 y0 x1 y1 exclusive) and classes."""

    def __init__(self, path, boxes, classes, source):
        self.path, self.boxes, self.classes, self.source = path, boxes, classes, source
        self.image = None

    def load(self):
        if self.image is None:
            self.image = cv2.imread(self.path, cv2.IMREAD_COLOR)
            if self.image is None:
                raise DataError(f"{self.path}: not a readable image")
        return self.image


def parse_class_map(text):
    """'0=door,1=handle,2=door,3=door' -> {0: 0, 1: 1, 2: 0, 3: 0}; classes not named are ignored."""
    mapping = {}
    for item in text.split(","):
        key, _, name = item.partition("=")
        if not key.strip().isdigit() or name.strip() not in CLASSES:
            raise DataError(f"--class-map: '{item}' is not ID=door or ID=handle")
        mapping[int(key)] = CLASSES.index(name.strip())
    return mapping


def read_yolo_folder(folder, class_map, source):
    """images/NAME.ext with labels/NAME.txt ('class cx cy w h', relative); an image without a
    label file has no objects."""
    image_dir = os.path.join(folder, "images")
    label_dir = os.path.join(folder, "labels")
    if not os.path.isdir(image_dir):
        raise DataError(f"{folder}: no images/ folder (a YOLO folder has images/ and labels/)")
    samples = []
    for name in sorted(os.listdir(image_dir)):
        stem, ext = os.path.splitext(name)
        if ext.lower() not in IMAGE_SUFFIXES:
            continue
        path = os.path.join(image_dir, name)
        boxes, classes = [], []
        label = os.path.join(label_dir, stem + ".txt")
        if os.path.exists(label):
            with open(label) as f:
                for number, line in enumerate(f, 1):
                    fields = line.split()
                    if not fields:
                        continue
                    try:
                        c, cx, cy, w, h = int(fields[0]), *map(float, fields[1:5])
                    except (ValueError, TypeError):
                        raise DataError(f"{label}:{number}: expected 'class cx cy w h'")
                    if len(fields) != 5 or not all(0 <= v <= 1.0001 for v in (cx, cy, w, h)):
                        raise DataError(f"{label}:{number}: expected 'class cx cy w h' in [0, 1]")
                    if c in class_map:
                        boxes.append((cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2))
                        classes.append(class_map[c])
        sample = Sample(path, np.array(boxes, np.float32).reshape(-1, 4), np.array(classes, np.int64), source)
        sample.relative = True
        samples.append(sample)
    if not samples:
        raise DataError(f"{image_dir}: no images")
    return samples


def read_box_labels(path, source):
    """The project's box-label YAML; boxes' corners are inclusive pixels."""
    try:
        with open(path) as f:
            root = yaml.safe_load(f)
    except (OSError, yaml.YAMLError) as e:
        raise DataError(f"{path}: {str(e).splitlines()[0]}")
    if not isinstance(root, dict) or not isinstance(root.get("images"), list):
        raise DataError(f"{path}: expected a map with an 'images' list")
    base = os.path.dirname(os.path.abspath(path))
    samples = []
    for i, entry in enumerate(root["images"]):
        if not isinstance(entry, dict) or "image" not in entry:
            raise DataError(f"{path}: images[{i}]: expected a map with 'image'")
        boxes, classes = [], []
        for j, box in enumerate(entry.get("boxes") or []):
            try:
                kind = box["type"]
                u0, v0, u1, v1 = (float(box[k]) for k in ("u_min", "v_min", "u_max", "v_max"))
            except (KeyError, TypeError, ValueError):
                raise DataError(f"{path}: images[{i}].boxes[{j}]: expected type, u_min, v_min, u_max, v_max")
            if kind in TYPE_CLASS and u1 >= u0 and v1 >= v0:
                boxes.append((u0, v0, u1 + 1, v1 + 1))
                classes.append(TYPE_CLASS[kind])
        sample = Sample(os.path.join(base, entry["image"]), np.array(boxes, np.float32).reshape(-1, 4),
                        np.array(classes, np.int64), source)
        sample.relative = False
        samples.append(sample)
    if not samples:
        raise DataError(f"{path}: no images")
    return samples


def read_labels(location, class_map, source):
    if os.path.isdir(location):
        return read_yolo_folder(location, class_map, source)
    if os.path.isfile(location):
        return read_box_labels(location, source)
    raise DataError(f"{location}: no such file or folder")


def pixel_boxes(sample):
    image = sample.load()
    if getattr(sample, "relative", False):
        h, w = image.shape[:2]
        return sample.boxes * np.array([w, h, w, h], np.float32)
    return sample.boxes.copy()


def split(samples, fraction, seed):
    """Deterministic split into (train, held out) by a seeded shuffle of the sorted paths."""
    order = sorted(range(len(samples)), key=lambda i: samples[i].path)
    random.Random(seed).shuffle(order)
    held = set(order[: int(round(fraction * len(samples)))])
    return ([s for i, s in enumerate(samples) if i not in held], [s for i, s in enumerate(samples) if i in held])


def letterbox(image, width, height):
    """Scales the image to fit width x height (aspect kept, bilinear as the C++ detector does),
    pads right and bottom with grey. Returns the input image and the scale (input pixels per
    image pixel)."""
    scale = min(width / image.shape[1], height / image.shape[0])
    resized = cv2.resize(image, (max(1, round(image.shape[1] * scale)), max(1, round(image.shape[0] * scale))),
                         interpolation=cv2.INTER_LINEAR)
    out = np.full((height, width, 3), 114, np.uint8)
    out[: resized.shape[0], : resized.shape[1]] = resized
    return out, scale


def augment(sample, width, height, rng):
    """A random training view: scale 0.6-1.6 of the fitted size, a random crop or placement,
    horizontal flip, colour and brightness jitter, sometimes grey, blur or JPEG noise. Boxes
    cut by the crop keep their visible part if at least 40 % of them remains."""
    image = sample.load()
    boxes = pixel_boxes(sample)
    fit = min(width / image.shape[1], height / image.shape[0])
    scale = fit * math.exp(rng.uniform(math.log(0.6), math.log(1.6)))
    aspect = math.exp(rng.uniform(-0.15, 0.15))
    sx, sy = scale * aspect, scale / aspect
    new_w, new_h = max(8, round(image.shape[1] * sx)), max(8, round(image.shape[0] * sy))
    resized = cv2.resize(image, (new_w, new_h), interpolation=cv2.INTER_AREA if scale < 1 else cv2.INTER_LINEAR)
    boxes = boxes * np.array([sx, sy, sx, sy], np.float32)
    dx = rng.randint(min(0, width - new_w), max(0, width - new_w))
    dy = rng.randint(min(0, height - new_h), max(0, height - new_h))
    canvas = np.full((height, width, 3), rng.randint(0, 255), np.uint8)
    x0, y0 = max(0, dx), max(0, dy)
    x1, y1 = min(width, dx + new_w), min(height, dy + new_h)
    canvas[y0:y1, x0:x1] = resized[y0 - dy : y1 - dy, x0 - dx : x1 - dx]
    boxes = boxes + np.array([dx, dy, dx, dy], np.float32)
    area = (boxes[:, 2] - boxes[:, 0]) * (boxes[:, 3] - boxes[:, 1])
    clipped = boxes.copy()
    clipped[:, [0, 2]] = clipped[:, [0, 2]].clip(x0, x1)
    clipped[:, [1, 3]] = clipped[:, [1, 3]].clip(y0, y1)
    kept_area = (clipped[:, 2] - clipped[:, 0]) * (clipped[:, 3] - clipped[:, 1])
    keep = (kept_area >= 0.4 * np.maximum(area, 1e-6)) & (clipped[:, 2] - clipped[:, 0] >= 2) & (clipped[:, 3] - clipped[:, 1] >= 2)
    boxes, classes = clipped[keep], sample.classes[keep]
    if rng.random() < 0.5:
        canvas = canvas[:, ::-1].copy()
        boxes = np.stack([width - boxes[:, 2], boxes[:, 1], width - boxes[:, 0], boxes[:, 3]], 1).reshape(-1, 4)
    canvas = jitter_colours(canvas, rng)
    return canvas, boxes.astype(np.float32), classes


def jitter_colours(image, rng):
    hsv = cv2.cvtColor(image, cv2.COLOR_BGR2HSV).astype(np.float32)
    hsv[..., 0] = (hsv[..., 0] + rng.uniform(-12, 12)) % 180
    hsv[..., 1] *= rng.uniform(0.5, 1.5)
    hsv[..., 2] *= rng.uniform(0.6, 1.4)
    image = cv2.cvtColor(hsv.clip(0, 255).astype(np.uint8), cv2.COLOR_HSV2BGR)
    if rng.random() < 0.1:
        image = cv2.cvtColor(cv2.cvtColor(image, cv2.COLOR_BGR2GRAY), cv2.COLOR_GRAY2BGR)
    if rng.random() < 0.2:
        image = cv2.GaussianBlur(image, (0, 0), rng.uniform(0.5, 1.5))
    if rng.random() < 0.2:
        ok, data = cv2.imencode(".jpg", image, [cv2.IMWRITE_JPEG_QUALITY, rng.randint(30, 90)])
        image = cv2.imdecode(data, cv2.IMREAD_COLOR)
    return image


def to_tensor_layout(image):
    """BGR uint8 HxWx3 -> float32 3xHxW RGB in [0, 1] (what the C++ detector feeds)."""
    return np.ascontiguousarray(image[..., ::-1].transpose(2, 0, 1), dtype=np.float32) / 255.0
