; a job of comments only
(nothing to cut)

