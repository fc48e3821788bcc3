//! Surface-nets quad meshing with quad classes and Ptex adjacency (Becher §4.5–4.6).
