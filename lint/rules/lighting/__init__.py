"""L, lighting: physically wrong shading that compiles and renders, just not as intended. Which
vector is the normal, the light or the view is read from names (see `_terms`), so every rule
here needs code written with the usual conventions and stays silent otherwise: a miss is
cheaper than a false alarm on correct code. One module per rule; helpers shared by the lighting
rules in `_common`, the vocabulary of shading code (roles of vectors, cosines, Fresnel terms) in
`_terms`; the analyses they build on in `lint/analysis`."""
