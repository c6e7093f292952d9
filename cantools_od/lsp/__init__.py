"""`cantools-od lsp`: a Language Server Protocol server for EDS, DCF and XDD/XDC files.

Every answer comes from the layers the commands use: the document's bytes are read by `api.loads`
into the model, checked by the lint runner, written by `api.dumps`; this package only maps model
origins (line and column of each section, key and XML element) to editor positions and back.
"""
