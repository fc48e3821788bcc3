//! Wire formats of the products.
