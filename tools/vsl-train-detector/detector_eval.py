"""Detections from the network's maps and their evaluation as PASCAL VOC does: per class,
detections sorted by confidence, each matched greedily to the unmatched ground-truth box of
highest IoU >= 0.5; AP50 the area under the interpolated precision-recall curve. The C++
detector (libs/recognition/src/learned_detector.cpp) decodes the same way."""
import numpy as np
import torch
import torch.nn.functional as F

from detector_targets import decode_boxes


def detect(net, images, stride, min_score=0.02, max_per_class=100, nms_iou=0.6):
    """images: B x 3 x H x W tensor -> per image a list of (class, score, x0, y0, x1, y1)."""
    with torch.no_grad():
        maps = net(images)
    num_classes = net.num_classes
    scores = torch.sigmoid(maps[:, :num_classes])
    peaks = scores * (scores == F.max_pool2d(scores, 3, 1, 1))
    boxes = decode_boxes(maps[:, num_classes:], stride)
    per_class = boxes.shape[1] == 4 * num_classes and num_classes > 1
    out = []
    for b in range(maps.shape[0]):
        found = []
        for c in range(num_classes):
            s = peaks[b, c].flatten()
            top = torch.topk(s, min(max_per_class, s.numel()))
            keep = top.values >= min_score
            idx = top.indices[keep]
            group = boxes[b, 4 * c : 4 * c + 4] if per_class else boxes[b, :4]
            cand = group.reshape(4, -1)[:, idx].T.numpy()
            for k in nms(cand, top.values[keep].numpy(), nms_iou):
                found.append((c, float(top.values[keep][k]), *map(float, cand[k])))
        out.append(found)
    return out


def iou(box, boxes):
    ix = np.clip(np.minimum(box[2], boxes[:, 2]) - np.maximum(box[0], boxes[:, 0]), 0, None)
    iy = np.clip(np.minimum(box[3], boxes[:, 3]) - np.maximum(box[1], boxes[:, 1]), 0, None)
    inter = ix * iy
    area = lambda b: (b[..., 2] - b[..., 0]) * (b[..., 3] - b[..., 1])
    return inter / np.maximum(area(box) + area(boxes) - inter, 1e-9)


def nms(boxes, scores, threshold):
    order = np.argsort(-scores)
    keep = []
    while order.size:
        k = order[0]
        keep.append(k)
        order = order[1:][iou(boxes[k], boxes[order[1:]]) <= threshold] if order.size > 1 else order[1:]
    return keep


def match(detections, truths, cls, iou_threshold=0.5):
    """detections: per image lists of (class, score, box...); truths: per image (boxes, classes).
    Returns (scores, is_true) of class `cls` sorted by score, and the number of ground truths."""
    records, total = [], 0
    for found, (boxes, classes) in zip(detections, truths):
        gt = boxes[classes == cls]
        total += len(gt)
        used = np.zeros(len(gt), bool)
        for d in sorted((d for d in found if d[0] == cls), key=lambda d: -d[1]):
            ok = False
            if len(gt):
                overlaps = iou(np.array(d[2:]), gt)
                overlaps[used] = -1
                k = int(np.argmax(overlaps))
                if overlaps[k] >= iou_threshold:
                    used[k] = ok = True
            records.append((d[1], ok))
    records.sort(key=lambda r: -r[0])
    return np.array([r[0] for r in records]), np.array([r[1] for r in records], bool), total


def pr_curve(scores, is_true, total):
    tp = np.cumsum(is_true)
    fp = np.cumsum(~is_true)
    recall = tp / max(total, 1)
    precision = tp / np.maximum(tp + fp, 1)
    return precision, recall


def average_precision(precision, recall):
    """VOC 2010+: area under the precision envelope (precision made monotone from the right)."""
    if len(precision) == 0:
        return 0.0
    p = np.concatenate([[0.0], precision, [0.0]])
    r = np.concatenate([[0.0], recall, [recall[-1]]])
    for i in range(len(p) - 2, -1, -1):
        p[i] = max(p[i], p[i + 1])
    return float(np.sum((r[1:] - r[:-1]) * p[1:]))


def best_f1_threshold(scores, is_true, total):
    """The confidence threshold maximizing F1 on these detections."""
    if len(scores) == 0:
        return 0.5
    precision, recall = pr_curve(scores, is_true, total)
    f1 = 2 * precision * recall / np.maximum(precision + recall, 1e-9)
    k = int(np.argmax(f1))
    return float(scores[k])


def at_threshold(scores, is_true, total, threshold):
    chosen = scores >= threshold
    tp = int(is_true[chosen].sum())
    n = int(chosen.sum())
    return (tp / n if n else 0.0), (tp / total if total else 0.0)


def cross_validated_thresholds(detections, truths, num_classes, seed=0):
    """Per class: the threshold chosen on one half of the images is scored on the other half and
    vice versa (2-fold); returns the thresholds chosen on all images and the cross-validated
    precision and recall (detections and truths pooled over both test halves)."""
    rng = np.random.default_rng(seed)
    half = rng.permutation(len(truths)) % 2
    result = []
    for c in range(num_classes):
        tp = fp_n = gt = 0
        for fold in (0, 1):
            def pick(which):
                return ([x for x, h in zip(detections, half) if h == which],
                        [x for x, h in zip(truths, half) if h == which])

            d_fit, t_fit = pick(1 - fold)
            d_test, t_test = pick(fold)
            threshold = best_f1_threshold(*match(d_fit, t_fit, c))
            s, ok, total = match(d_test, t_test, c)
            chosen = s >= threshold
            tp += int(ok[chosen].sum())
            fp_n += int((~ok[chosen]).sum())
            gt += total
        s, ok, total = match(detections, truths, c)
        precision, recall = pr_curve(s, ok, total)
        result.append({
            "threshold": best_f1_threshold(s, ok, total),
            "cv_precision": tp / max(tp + fp_n, 1),
            "cv_recall": tp / max(gt, 1),
            "ap50": average_precision(precision, recall),
            "objects": total,
        })
    return result
