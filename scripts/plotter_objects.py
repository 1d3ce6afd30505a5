#!/usr/bin/env python3
"""Writes the plotter's example programs (resources/programs/plotter_*.G) from the objects
of seed 001 (UNESC 2014): the square of figure 44 and the rectangle of figure 48 with the
seed's own coordinates; the triangle, the 25-point spiral, the 74-point text and the 50-point
circle that table 8 timed, whose coordinates the seed does not give (annex H is a picture),
drawn again here with the seed's point counts. Points are step counts, as the seed's MOVE/LINE
packets carry them; the programs are in mm at 0.1 mm a step (resources/machines/
xy_plotter.json). Run from the repository root: python3 scripts/plotter_objects.py"""
import math
import pathlib

MM_PER_STEP = 0.1
FEED = 45  # percent of plotter.maxStepRateHz 1000: 450 events/s, the rate of figure 48

# Stroke font on a 4 x 6 grid: each letter a list of strokes (polylines).
FONT = {
    "T": [[(0, 6), (4, 6)], [(2, 6), (2, 0)]],
    "C": [[(4, 6), (1, 6), (0, 5), (0, 1), (1, 0), (4, 0)]],
    "U": [[(0, 6), (0, 1), (1, 0), (3, 0), (4, 1), (4, 6)]],
    "N": [[(0, 0), (0, 6), (4, 0), (4, 6)]],
    "E": [[(4, 6), (0, 6), (0, 0), (4, 0)], [(0, 3), (3, 3)]],
    "S": [[(4, 5), (3, 6), (1, 6), (0, 5), (0, 4), (1, 3), (3, 3), (4, 2), (4, 1), (3, 0),
           (1, 0), (0, 1)]],
    "2": [[(0, 5), (1, 6), (3, 6), (4, 5), (4, 4), (3, 3), (0, 0), (4, 0)]],
    "0": [[(1, 0), (0, 1), (0, 5), (1, 6), (3, 6), (4, 5), (4, 1), (3, 0), (1, 0)]],
    "1": [[(1, 5), (2, 6), (2, 0)]],
    "4": [[(3, 0), (3, 6), (0, 2), (4, 2)]],
    " ": [],
}


def polyline(points):
    return [points]


def square_fig44():
    return [[(366, 202), (366, 360), (508, 360), (508, 202), (366, 202)]]


def rectangle_fig48():
    return [[(644, 314), (644, 454), (884, 454), (884, 314), (644, 314)]]


def triangle():
    return [[(1000, 300), (1600, 300), (1300, 820), (1000, 300)]]


def spiral():
    # Archimedean, three turns, 25 points, about (1500, 1000).
    pts = []
    for i in range(25):
        a = i * 3 * 2 * math.pi / 24
        r = 30 + 25 * i
        pts.append((round(1500 + r * math.cos(a)), round(1000 + r * math.sin(a))))
    return [pts]


def circle():
    # 50 points: 49 vertices and the first again to close it; radius 500 about (2300, 1200).
    pts = []
    for i in range(50):
        a = (i % 49) * 2 * math.pi / 49
        pts.append((round(2300 + 500 * math.cos(a)), round(1200 + 500 * math.sin(a))))
    return [pts]


def text(s="TCC UNESC 2014", x0=200, y0=1700, unit=25, advance=6):
    strokes = []
    for k, ch in enumerate(s):
        for stroke in FONT[ch]:
            strokes.append([(x0 + (k * advance + gx) * unit, y0 + gy * unit) for gx, gy in stroke])
    return strokes


def mm(v):
    return f"{v * MM_PER_STEP:.1f}"


def program(name, title, source, strokes):
    count = sum(len(s) for s in strokes)
    lines = [f"; {title} ({count} points), seed 001 (UNESC 2014) on the xy-plotter profile.",
             f"; {source}",
             "; Seed points are step counts; here mm at 0.1 mm a step. G00 = MOVE (pen up),",
             "; G01 = LINE (pen down). Written by scripts/plotter_objects.py.",
             "%", "G90"]
    first_feed = True
    for stroke in strokes:
        x, y = stroke[0]
        lines.append(f"G00 X{mm(x)} Y{mm(y)}  ( MOVE {x},{y} )")
        for x, y in stroke[1:]:
            feed = f" F{FEED}" if first_feed else ""
            first_feed = False
            lines.append(f"G01 X{mm(x)} Y{mm(y)}{feed}  ( LINE {x},{y} )")
    lines += ["M02", "%", ""]
    pathlib.Path(f"resources/programs/{name}").write_text("\n".join(lines))
    return count


OBJECTS = [
    ("plotter_quadrado.G", "Square", "Coordinates of figure 44 (the MOVE/LINE packets sent).",
     square_fig44()),
    ("plotter_retangulo_fig48.G", "Rectangle", "Coordinates of figure 48 (object 0 of the log).",
     rectangle_fig48()),
    ("plotter_triangulo.G", "Triangle",
     "Chosen coordinates: table 8 times a triangle, annex H shows it only as a picture.",
     triangle()),
    ("plotter_espiral.G", "Spiral",
     "Chosen coordinates with table 8's count (25 points); annex H is a picture.", spiral()),
    ("plotter_texto.G", "Text",
     "Chosen coordinates with table 8's count (74 points); annex H is a picture.", text()),
    ("plotter_circulo.G", "Circle",
     "Chosen coordinates with table 8's count (50 points); annex H is a picture.", circle()),
]

if __name__ == "__main__":
    for name, title, source, strokes in OBJECTS:
        print(name, program(name, title, source, strokes))
