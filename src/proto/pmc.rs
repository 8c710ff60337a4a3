//! PMC areas.
