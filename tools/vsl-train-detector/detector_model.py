"""The door and handle detector's network: a compact fully convolutional one-stage detector.

Backbone: a 3x3 stem and depthwise-separable residual stages down to stride 32 (the receptive
field a whole door needs); a feature pyramid merges the stages back to stride 4 (a handle 10 px
long in a 640 px image is 7 px at the 448 px input, under two output cells at stride 4). The head
predicts, per output cell, one logit per class (a Gaussian "centre-ness" map, TTFNet) and four
log-distances from the cell's centre to the box's left, top, right and bottom sides in input
pixels. Only operators OpenCV's dnn runs fast on one core (Conv, BatchNorm folded at export,
ReLU, Add, nearest Resize).
"""
import torch
from torch import nn
import torch.nn.functional as F

STRIDE = 4


def conv_bn(cin, cout, k=3, s=1, groups=1, relu=True):
    layers = [nn.Conv2d(cin, cout, k, s, k // 2, groups=groups, bias=False), nn.BatchNorm2d(cout)]
    if relu:
        layers.append(nn.ReLU(inplace=True))
    return nn.Sequential(*layers)


class SeparableBlock(nn.Module):
    """Depthwise k x k then pointwise 1x1; residual when shape is kept."""

    def __init__(self, cin, cout, stride=1, k=3):
        super().__init__()
        self.dw = conv_bn(cin, cin, k, stride, groups=cin)
        self.pw = conv_bn(cin, cout, 1, relu=False)
        self.residual = stride == 1 and cin == cout

    def forward(self, x):
        y = self.pw(self.dw(x))
        return F.relu(y + x if self.residual else y)


def stage(cin, cout, blocks, k=3):
    return nn.Sequential(SeparableBlock(cin, cout, 2, k), *[SeparableBlock(cout, cout, 1, k) for _ in range(blocks - 1)])


# The deep stages' channels and blocks (stride 16, stride 32) unless a checkpoint says otherwise:
# checkpoints store them as "deep" and "deep_blocks"; older ones, without them, are (128, 192) and
# (3, 2).
DEEP = (128, 192)
DEEP_BLOCKS = (3, 2)


class DoorHandleDetector(nn.Module):
    def __init__(self, num_classes=2, width=1.0, deep=DEEP, deep_blocks=DEEP_BLOCKS,
                 box_per_class=False):
        super().__init__()
        # One box per class at each cell, or one shared by the classes (the older models): with a
        # shared box, a drawer front whose centre is its handle's is given the handle's box.
        self.box_groups = num_classes if box_per_class else 1
        c = [int(round(v * width)) for v in (16, 32, 64, *deep)]
        self.num_classes, self.width = num_classes, width
        self.deep, self.deep_blocks = tuple(deep), tuple(deep_blocks)
        # stride 4: a full 3x3 convolution, then a separable one (a full one here costs 3x)
        self.stem = nn.Sequential(conv_bn(3, c[0], 3, 2), conv_bn(c[0], c[0], 3, 2, groups=c[0]),
                                  conv_bn(c[0], c[1], 1))
        self.s8 = stage(c[1], c[2], 2)
        self.s16 = stage(c[2], c[3], deep_blocks[0])
        self.s32 = stage(c[3], c[4], deep_blocks[1], k=5)
        f, f4 = 64, 32  # pyramid channels; fewer at stride 4, where each layer costs the most
        self.lat32 = conv_bn(c[4], f, 1)
        self.lat16 = conv_bn(c[3], f, 1)
        self.lat8 = conv_bn(c[2], f, 1)
        self.smooth16 = SeparableBlock(f, f)
        self.smooth8 = nn.Sequential(SeparableBlock(f, f), conv_bn(f, f4, 1))
        self.lat4 = conv_bn(c[1], f4, 1)
        self.head = nn.Sequential(conv_bn(f4, f4, 3, groups=f4), conv_bn(f4, f4, 1),
                                  nn.Conv2d(f4, num_classes + 4 * self.box_groups, 1))
        nn.init.constant_(self.head[-1].bias[:num_classes], -4.6)  # initial centre-ness 0.01
        nn.init.constant_(self.head[-1].bias[num_classes:], 2.0)   # sides ~7 px away

    def forward(self, x):
        x4 = self.stem(x)
        x8 = self.s8(x4)
        x16 = self.s16(x8)
        x32 = self.s32(x16)
        up = lambda t: F.interpolate(t, scale_factor=2.0, mode="nearest")
        p16 = self.smooth16(self.lat16(x16) + up(self.lat32(x32)))
        p8 = self.smooth8(self.lat8(x8) + up(p16))
        return self.head(self.lat4(x4) + up(p8))


def checkpoint(net, **extra):
    """What a .pt file holds: the weights and the shape they fill (load_state reads them into a
    network of that shape or a larger one)."""
    return {"weights": net.state_dict(), "width": net.width, "deep": net.deep,
            "deep_blocks": net.deep_blocks, "box_per_class": net.box_groups > 1, **extra}


def load_state(net, weights):
    """Loads `weights` (a state dict) into `net`, which may be wider or deeper in its deep stages
    than the network they were trained in (Net2Net, Chen et al. 2016: the grown network computes
    the same function at first). Each tensor is copied into the leading part of its namesake. A
    convolution reading new input channels reads them with zero weights, so what the new
    channels carry does not reach the old outputs until training makes it; a new residual block
    starts with its last batch norm's scale at zero, so it passes its input through unchanged.
    A network with a box per class grown from one with a shared box starts with the shared box's
    maps for every class.
    New output channels keep their random initialization: the zero weights reading them still
    receive gradients."""
    own = net.state_dict()
    head = "head.2."  # the last convolution: classes' centre-ness, then 4 box sides per group
    for name in (head + "weight", head + "bias"):
        old, new = weights.get(name), own.get(name)
        if old is not None and new is not None and old.shape[0] == net.num_classes + 4 and \
                new.shape[0] > old.shape[0]:
            # A box per class from the shared one: each class starts with the shared box's maps.
            weights = dict(weights)
            shared = old[net.num_classes:]
            weights[name] = torch.cat([old[: net.num_classes]] + [shared] * net.box_groups)
    dropped = [name for name in weights if name not in own]
    if dropped:
        raise RuntimeError(f"{dropped[0]}: not in the network (fewer blocks than the weights' cannot grow)")
    grown = {}
    for name, value in own.items():
        if name not in weights:
            if name.endswith("pw.1.weight"):  # a new block's closing batch norm: identity block
                value = torch.zeros_like(value)
            grown[name] = value
            continue
        old = weights[name]
        if old.shape == value.shape:
            grown[name] = old
            continue
        if old.dim() != value.dim() or any(o > n for o, n in zip(old.shape, value.shape)) or \
                old.shape[2:] != value.shape[2:]:
            raise RuntimeError(f"{name}: {tuple(old.shape)} cannot grow into {tuple(value.shape)}")
        value = value.clone()
        if value.dim() == 4 and value.shape[1] > 1:  # a convolution across channels
            value[: old.shape[0], old.shape[1]:] = 0.0
        elif name.endswith(("running_mean", "bias")) and value.dim() == 1:
            value[old.shape[0]:] = 0.0
        value[tuple(slice(0, n) for n in old.shape)] = old
        grown[name] = value
    net.load_state_dict(grown)
