"""Executes a notebook as Jupyter would (nbclient, the python3 kernel of Debian's ipykernel), in its
own folder, and fails on the first cell that raises or on a notebook that shows no picture."""

import os
import sys

import nbclient
import nbformat



class Client(nbclient.NotebookClient):
    # Debian's ipywidgets 6 opens a widget's comm without the "state" that nbclient 0.7 reads.
    def on_comm_open_jupyter_widget(self, msg):
        if "state" not in msg["content"]["data"]:
            return None
        return super().on_comm_open_jupyter_widget(msg)


path = sys.argv[1]
notebook = nbformat.read(path, as_version=4)
client = Client(notebook, timeout=600, kernel_name="python3",
                                 resources={"metadata": {"path": os.path.dirname(os.path.abspath(path))}})
client.execute()
pictures = sum(1 for cell in notebook.cells if cell.cell_type == "code" for out in cell.get("outputs", [])
               if "image/png" in out.get("data", {}))
interactive = [cell for cell in notebook.cells if cell.cell_type == "code" and "interact(" in cell.source]
drawn_by_sliders = sum(1 for cell in interactive for out in cell.get("outputs", []) if "image/png" in out.get("data", {}))
print(f"{path}: {len(notebook.cells)} cells run, {pictures} pictures shown, {drawn_by_sliders} drawn by the sliders' function")
# Every picture cell showed its picture, and interact() drew once with the sliders' first values.
if pictures < 6 or not interactive or drawn_by_sliders < 1:
    sys.exit(f"{path}: expected at least 6 pictures, one of them drawn through interact(), got {pictures} and {drawn_by_sliders}")
