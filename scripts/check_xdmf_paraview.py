"""Open an XDMF file written by `mcrash export --xdmf` (or --xdmf2) in ParaView and print
what ParaView reads at the last time step (or at --time T): points, cells, number of time steps, the lowest z
of the deformed shape (points + displacement for XDMF 3, as Warp By Vector shows it; the
geometry itself for XDMF 2, where it is already deformed), and the orientation quaternion
components w and y of the rigid body with the highest body_id.

    pvpython scripts/check_xdmf_paraview.py OUT.xmf            # Xdmf3 reader (XDMF 3)
    pvpython scripts/check_xdmf_paraview.py --xdmf2 OUT.xmf    # legacy XDMF reader
    pvpython scripts/check_xdmf_paraview.py --time 0.02 OUT.xmf

pvpython comes with the Debian package python3-paraview (optional for mcrash).
Output: "xdmf: points N cells N timesteps N last T zmin Z q W Y" (last: the time shown); exit 1 if nothing was read."""
import os
import sys

from paraview import simple
from paraview import servermanager
from paraview.vtk.util.numpy_support import vtk_to_numpy


def leaves(obj):
    """every dataset in a (possibly nested) composite data set"""
    if obj is None:
        return
    if obj.IsA("vtkCompositeDataSet"):
        it = obj.NewIterator()
        it.InitTraversal()
        while not it.IsDoneWithTraversal():
            yield it.GetCurrentDataObject()
            it.GoToNextItem()
    else:
        yield obj


def main(path, legacy, at):
    # the Xdmf readers resolve the .h5 against the directory of the .xmf: give them one
    path = os.path.abspath(path)
    if legacy:
        reader = simple.XDMFReader(FileNames=[path])
    else:
        reader = simple.Xdmf3ReaderS(FileName=[path])
    times = list(reader.TimestepValues) if reader.TimestepValues else [0.0]
    last = times[-1] if at is None else at
    reader.UpdatePipeline(last)
    data = servermanager.Fetch(reader)
    npts = ncells = 0
    zmin = float("inf")
    quat = (float("nan"), float("nan"))
    best_id = -1
    for ds in leaves(data):
        if ds is None or ds.GetNumberOfPoints() == 0:
            continue
        npts += ds.GetNumberOfPoints()
        ncells += ds.GetNumberOfCells()
        pd = ds.GetPointData()
        z = vtk_to_numpy(ds.GetPoints().GetData())[:, 2]
        disp = pd.GetArray("displacement")
        if disp is not None and not legacy:
            z = z + vtk_to_numpy(disp)[:, 2]
        zmin = min(zmin, float(z.min()))
        ori, bid = pd.GetArray("orientation"), pd.GetArray("body_id")
        if ori is not None and bid is not None:
            q = vtk_to_numpy(ori).reshape(-1)
            i = int(vtk_to_numpy(bid).reshape(-1)[0])
            if i > best_id:
                best_id, quat = i, (float(q[0]), float(q[2]))
    print("xdmf: points %d cells %d timesteps %d last %.17g zmin %.17g q %.17g %.17g"
          % (npts, ncells, len(times), last, zmin, quat[0], quat[1]))
    return 0 if npts > 0 else 1


if __name__ == "__main__":
    args = sys.argv[1:]
    legacy = "--xdmf2" in args
    args = [a for a in args if a != "--xdmf2"]
    at = None
    if len(args) == 3 and args[0] == "--time":
        at = float(args[1])
        args = args[2:]
    if len(args) != 1:
        print("usage: pvpython check_xdmf_paraview.py [--xdmf2] [--time T] FILE.xmf",
              file=sys.stderr)
        sys.exit(2)
    sys.exit(main(args[0], legacy, at))
