"""Grid assignment refuses bad input by name: cells off the grid or on obstacles, walled-off
robots and goals, malformed MovingAI map and voxel files (file and line)."""

from __future__ import annotations

import numpy as np
import pytest

from agents.assignment import AssignmentError, assign_on_grid
from agents.assignment.grid import load_movingai_map, load_voxel_map

GRID_2D = np.zeros((4, 5), dtype=bool)
GRID_2D[1, 1] = True
GRID_3D = np.zeros((3, 4, 5), dtype=bool)
GRID_3D[1, 1, 1] = True


@pytest.mark.parametrize("grid, robots, goals, pattern", [
    (GRID_2D, [[0, 0], [-1, 2]], [[2, 2], [3, 3]], r"robots\[1\] = \[-1, 2\] is outside the 4 x 5 grid"),
    (GRID_2D, [[0, 0], [0, 5]], [[2, 2], [3, 3]], r"robots\[1\] = \[0, 5\] is outside"),
    (GRID_2D, [[1, 1]], [[2, 2]], r"robots\[0\] = \[1, 1\] is on an obstacle"),
    (GRID_2D, [[0, 0]], [[2, 2], [3, 3], [4, 0]], r"goals\[2\] = \[4, 0\] is outside"),
    (GRID_2D, [[0, 0]], [[2, 2], [1, 1]], r"goals\[1\] = \[1, 1\] is on an obstacle"),
    (GRID_2D, [[0, 0.5]], [[2, 2]], r"robots\[0\] = \[0.0, 0.5\] is not a cell"),
    (GRID_2D, [[0, 0, 0]], [[2, 2]], r"robots must have shape \(count, 2\)"),
    (GRID_3D, [[0, 0, 0], [2, 3, 5]], [[2, 2, 2], [0, 3, 4]], r"robots\[1\] = \[2, 3, 5\] is outside the 3 x 4 x 5"),
    (GRID_3D, [[0, 0, 0]], [[1, 1, 1]], r"goals\[0\] = \[1, 1, 1\] is on an obstacle"),
    (GRID_3D, [[0, 0]], [[1, 2, 1]], r"robots must have shape \(count, 3\) for a 3-D grid"),
])
def test_cells_off_the_grid_or_on_obstacles_are_refused_by_index(grid, robots, goals, pattern):
    for method in ("lazy", "all-pairs"):
        with pytest.raises(AssignmentError, match=pattern):
            assign_on_grid(grid, robots, goals, method=method)


def _walled_2d() -> np.ndarray:
    """5 x 5, row 3 a wall; cell (4, 0) is closed in by (4, 1) too: a pocket of one cell."""
    grid = np.zeros((5, 5), dtype=bool)
    grid[3, :] = True
    grid[4, 1] = True
    return grid


@pytest.mark.parametrize("robots, goals, pattern", [
    # As many robots as goals: the pocketed goal is named, not a robot of the short region.
    ([[0, 0], [0, 1]], [[4, 0], [1, 1]], r"goal 0 at cell \[4, 0\] cannot be reached by any robot"),
    ([[0, 0], [4, 0]], [[1, 1], [2, 2]], r"robot 1 at cell \[4, 0\] cannot reach any goal"),
    ([[0, 0], [0, 1], [0, 2]], [[1, 1], [4, 0]], r"goal 1 at cell \[4, 0\] cannot be reached"),
    ([[0, 0], [4, 0]], [[1, 1], [2, 2], [2, 3]], r"robot 1 at cell \[4, 0\] cannot reach any goal"),
    # Two robots and one goal above the wall, the other goals below it.
    ([[0, 0], [0, 1]], [[1, 1], [4, 3], [4, 4]],
     r"robot 0 at cell \[0, 0\] cannot be given a goal: .* 2 robots but only 1 goal$"),
])
def test_walled_off_robots_and_goals_are_named_by_both_methods(robots, goals, pattern):
    for method in ("lazy", "all-pairs"):
        with pytest.raises(AssignmentError, match=pattern):
            assign_on_grid(_walled_2d(), robots, goals, method=method)


def test_a_walled_off_goal_that_no_robot_needs_is_no_error():
    result = assign_on_grid(_walled_2d(), [[0, 0]], [[4, 0], [2, 4]])
    assert result.target_of.tolist() == [1]


def test_walled_off_voxel_in_3d_is_named():
    grid = np.zeros((4, 4, 4), dtype=bool)
    grid[2, :, :] = True  # a floor between x < 2 and x = 3
    with pytest.raises(AssignmentError, match=r"goal 1 at cell \[3, 0, 0\] cannot be reached by any robot"):
        assign_on_grid(grid, [[0, 0, 0], [1, 1, 1]], [[0, 3, 3], [3, 0, 0]])


def test_unknown_lower_bound_is_refused():
    with pytest.raises(AssignmentError, match="unknown lower bound 'manhattan'"):
        assign_on_grid(GRID_2D, [[0, 0]], [[2, 2]], lower_bound="manhattan")


HEADER = "type octile\nheight 2\nwidth 3\nmap\n"


@pytest.mark.parametrize("text, line, pattern", [
    ("", 1, "the file ends before the header line 'type'"),
    ("type octile\nheight 2\n", 3, "the file ends before the header line 'width'"),
    ("type octile\nwidth 3\nheight 2\nmap\n...\n...\n", 2, "expected header line 'height', got 'width 3'"),
    ("type octile\nheight two\nwidth 3\nmap\n...\n...\n", 2, "height must be a positive integer, got 'two'"),
    ("type octile\nheight 2\nwidth 0\nmap\n...\n...\n", 3, "width must be a positive integer"),
    ("type octile\nheight 2\nwidth 3 4\nmap\n...\n...\n", 3, "header line 'width' must be 'width VALUE'"),
    ("type octile\nheight 2\nwidth 3\nmap now\n...\n...\n", 4, "the .map. line must hold only the word .map."),
    ("\ntype tiles\nheight 2\nwidth 3\nmap\n...\n...\n", 2, "only 'type octile' maps are supported"),
    (HEADER + "...\n..\n", 6, "row 1 has 2 cells but the header says width 3"),
    (HEADER + "...\n.?.\n", 6, "unknown terrain '\\?' at column 1"),
    (HEADER + "...\n", 5, "the map ends after 1 of the 2 rows"),
    (HEADER + "...\n...\n...\n", 7, "a row beyond the 2 rows"),
    (HEADER + "...\n.\u00e9.\n", 6, "unknown terrain '\u00e9' at column 1"),
])
def test_malformed_map_files_are_refused_naming_file_and_line(tmp_path, text, line, pattern):
    path = tmp_path / "broken.map"
    path.write_bytes(text.encode("latin-1"))
    with pytest.raises(AssignmentError, match=rf"broken\.map, line {line}: {pattern}"):
        load_movingai_map(path)


def test_a_well_formed_map_with_windows_line_ends_and_trailing_blank_lines_loads(tmp_path):
    path = tmp_path / "ok.map"
    path.write_bytes(b"type octile\r\nheight 2\r\nwidth 3\r\nmap\r\n.T.\r\nG@S\r\n\r\n")
    assert load_movingai_map(path).tolist() == [[False, True, False], [False, True, False]]


def test_a_missing_map_file_is_named(tmp_path):
    with pytest.raises(AssignmentError, match=r"nothing\.map: cannot read the map file"):
        load_movingai_map(tmp_path / "nothing.map")


@pytest.mark.parametrize("text, line, pattern", [
    ("", 1, "empty file"),
    ("voxel 2 2\n", 1, "expected 'voxel X Y Z'"),
    ("voxel 2 2 2\n0 0 0\n0 0 x\n", 3, "expected a voxel 'x y z' of three integers"),
    ("voxel 2 2 2\n0 0 0\n\n1 2 0\n", 4, r"voxel \[1, 2, 0\] is outside the 2 x 2 x 2 map"),
    ("voxel 2 2 2\n-1 0 0\n", 2, r"voxel \[-1, 0, 0\] is outside"),
])
def test_malformed_voxel_files_are_refused_naming_file_and_line(tmp_path, text, line, pattern):
    path = tmp_path / "broken.3dmap"
    path.write_text(text)
    with pytest.raises(AssignmentError, match=rf"broken\.3dmap, line {line}: {pattern}"):
        load_voxel_map(path)


def test_a_voxel_map_loads_and_routes_around_its_voxels(tmp_path):
    path = tmp_path / "box.3dmap"
    path.write_text("voxel 3 3 1\n1 0 0\n1 1 0\n")
    grid = load_voxel_map(path)
    assert grid.shape == (3, 3, 1) and grid.sum() == 2
    # Around the wall through y = 2, six axis steps: every diagonal would cut the corner of (1, 1).
    for method in ("lazy", "all-pairs"):
        assert assign_on_grid(grid, [[0, 0, 0]], [[2, 0, 0]], method=method).total == 6.0
