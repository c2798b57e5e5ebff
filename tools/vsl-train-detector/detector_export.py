"""Export of a trained detector to ONNX for OpenCV's dnn (libs/recognition's learned detector)."""
import io

import onnx
from onnx import numpy_helper
import torch


def _inline_identities(model):
    """torch's exporter shares equal constant tensors (the folded biases of batch norms) through
    Identity nodes, which OpenCV 4.6's importer refuses; give each user its own copy instead."""
    inits = {t.name: t for t in model.graph.initializer}
    keep = []
    for node in model.graph.node:
        if node.op_type == "Identity" and node.input[0] in inits:
            copy = numpy_helper.from_array(numpy_helper.to_array(inits[node.input[0]]), node.output[0])
            model.graph.initializer.append(copy)
        else:
            keep.append(node)
    del model.graph.node[:]
    model.graph.node.extend(keep)
    return model


def export_onnx(net, path, height, width):
    net = net.eval()
    buffer = io.BytesIO()
    with torch.no_grad():
        torch.onnx.export(net, torch.zeros(1, 3, height, width), buffer, opset_version=11,
                          input_names=["image"], output_names=["maps"], do_constant_folding=True)
    model = _inline_identities(onnx.load_from_string(buffer.getvalue()))
    onnx.checker.check_model(model)
    onnx.save(model, path)


def export_refiner_onnx(refiner, path, crop):
    """The box refiner: input "crops" N x 3 x crop x crop (any N), output "sides" N x 5 (four
    sides and a logit)."""
    refiner = refiner.eval()
    buffer = io.BytesIO()
    with torch.no_grad():
        torch.onnx.export(refiner, torch.zeros(1, 3, crop, crop), buffer, opset_version=11,
                          input_names=["crops"], output_names=["sides"], do_constant_folding=True,
                          dynamic_axes={"crops": {0: "n"}, "sides": {0: "n"}})
    model = _inline_identities(onnx.load_from_string(buffer.getvalue()))
    onnx.checker.check_model(model)
    onnx.save(model, path)
