//! Axes and spindles: names, positions, speeds, loads, dynamic data, figures.
