"""Training targets and losses of the detector (TTFNet: Liu et al., "Training-Time-Friendly
Network for Real-Time Object Detection", AAAI 2020), chosen because it trains in a fraction of
CenterNet's epochs, which matters on a CPU.

For a box of width w and height h (input pixels) centred at c, the centre-ness target of its class
at output cell centre x is an elliptical Gaussian
    G(x) = exp(-(x_u - c_u)^2 / (2 s_u^2) - (x_v - c_v)^2 / (2 s_v^2)),  s = alpha (w, h) / 6,
maximum 1 at the cell holding c (a positive); the focal loss of CenterNet (Zhou et al. 2019, Eq. 1)
    L_c = -1/N sum { (1 - p)^2 log p                 where G = 1
                   { (1 - G)^4 p^2 log(1 - p)        elsewhere
The box is regressed at every cell where G > 0.01, as distances exp(d) from the cell's centre to
the four sides, with GIoU loss weighted by G normalized to log(area) per box, so that large boxes
do not drown small ones (TTFNet Eq. 5). Smaller boxes are drawn last and own shared cells. With a
box per class (box_groups = the number of classes) each class's boxes are drawn in maps of their
own: a drawer front and its handle share a centre, and with one shared box the front's cells
belong to the handle, so the door class learns the handle's box there.
"""
import math

import numpy as np
import torch

ALPHA = 0.54
MIN_GAUSSIAN = 0.01


def build_targets(boxes, classes, num_classes, out_h, out_w, stride, box_groups=1):
    """Centre-ness (classes x h x w), box targets (4 box_groups x h x w) and their weights
    (box_groups x h x w)."""
    heat = np.zeros((num_classes, out_h, out_w), np.float32)
    box_target = np.zeros((box_groups, 4, out_h, out_w), np.float32)
    weight = np.zeros((box_groups, out_h, out_w), np.float32)
    ys = (np.arange(out_h, dtype=np.float32) + 0.5) * stride
    xs = (np.arange(out_w, dtype=np.float32) + 0.5) * stride
    areas = (boxes[:, 2] - boxes[:, 0]) * (boxes[:, 3] - boxes[:, 1])
    for k in np.argsort(-areas):
        x0, y0, x1, y1 = boxes[k]
        cu, cv = (x0 + x1) / 2, (y0 + y1) / 2
        su = max(ALPHA * (x1 - x0) / 6, stride / 4)
        sv = max(ALPHA * (y1 - y0) / 6, stride / 4)
        gu = np.exp(-((xs - cu) ** 2) / (2 * su * su))
        gv = np.exp(-((ys - cv) ** 2) / (2 * sv * sv))
        g = gv[:, None] * gu[None, :]
        i = min(out_h - 1, max(0, int(cv // stride)))
        j = min(out_w - 1, max(0, int(cu // stride)))
        g[i, j] = 1.0
        heat[classes[k]] = np.maximum(heat[classes[k]], g)
        region = g > MIN_GAUSSIAN
        region[i, j] = True
        w = g * region
        w *= math.log(max(areas[k] / (stride * stride), 1.0) + 1.0) / w.sum()
        group = classes[k] if box_groups > 1 else 0
        box_target[group][:, region] = np.array([x0, y0, x1, y1], np.float32)[:, None]
        weight[group][region] = w[region]
    return heat, box_target.reshape(4 * box_groups, out_h, out_w), weight


def cell_centres(out_h, out_w, stride, device=None):
    ys = (torch.arange(out_h, device=device, dtype=torch.float32) + 0.5) * stride
    xs = (torch.arange(out_w, device=device, dtype=torch.float32) + 0.5) * stride
    return xs.view(1, out_w).expand(out_h, out_w), ys.view(out_h, 1).expand(out_h, out_w)


def decode_boxes(distances, stride):
    """B x 4G x h x w log-distances -> B x 4G x h x w boxes (x0, y0, x1, y1 per group G),
    input pixels."""
    d = torch.exp(distances.clamp(-2.0, 7.0))
    cx, cy = cell_centres(d.shape[2], d.shape[3], stride, d.device)
    sides = [cx - d[:, 0::4], cy - d[:, 1::4], cx + d[:, 2::4], cy + d[:, 3::4]]  # B x G x h x w
    return torch.stack(sides, 2).flatten(1, 2)


def focal_loss(logits, heat):
    p = torch.sigmoid(logits).clamp(1e-4, 1 - 1e-4)
    positive = heat >= 1.0
    pos_loss = ((1 - p) ** 2 * torch.log(p))[positive].sum()
    neg_loss = ((1 - heat) ** 4 * p**2 * torch.log(1 - p))[~positive].sum()
    return -(pos_loss + neg_loss) / positive.sum().clamp(min=1)


def giou_loss(pred, target, weight):
    """pred, target: B x 4G x h x w boxes; weight: B x G x h x w."""
    b, g, h, w_ = weight.shape
    pred, target, weight = pred.reshape(b * g, 4, h, w_), target.reshape(b * g, 4, h, w_), weight.reshape(b * g, h, w_)
    mask = weight > 0
    if not mask.any():
        return pred.sum() * 0
    p = pred.permute(0, 2, 3, 1)[mask]
    t = target.permute(0, 2, 3, 1)[mask]
    w = weight[mask]
    area_p = (p[:, 2] - p[:, 0]) * (p[:, 3] - p[:, 1])
    area_t = (t[:, 2] - t[:, 0]) * (t[:, 3] - t[:, 1])
    iw = (torch.min(p[:, 2], t[:, 2]) - torch.max(p[:, 0], t[:, 0])).clamp(min=0)
    ih = (torch.min(p[:, 3], t[:, 3]) - torch.max(p[:, 1], t[:, 1])).clamp(min=0)
    inter = iw * ih
    union = area_p + area_t - inter
    iou = inter / union.clamp(min=1e-6)
    ew = torch.max(p[:, 2], t[:, 2]) - torch.min(p[:, 0], t[:, 0])
    eh = torch.max(p[:, 3], t[:, 3]) - torch.min(p[:, 1], t[:, 1])
    enclosing = (ew * eh).clamp(min=1e-6)
    giou = iou - (enclosing - union) / enclosing
    return ((1 - giou) * w).sum() / w.sum().clamp(min=1e-6)
