//! Tool and work offsets.
